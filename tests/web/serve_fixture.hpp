// The server tests' fixture: a small study on disk (one-mode parameter sets with distinctive stimulus
// names), `serve` run in-process on a free loopback port, and requests as the browser client sends them.
#pragma once
#include <gtest/gtest.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "studyapp/core/results_store.hpp"
#include "studyapp/web/study_server.hpp"
#include "support/test_util.hpp"
#include "web/answer_body.hpp"
#include "web/http_client.hpp"

namespace ms::test {

inline std::string write_web_study(const TempDir& dir) {
  const std::string set = "sample_rate: 44100\nduration_s: 0.3\nmodes:\n  - {freq_hz: FREQ, decay_per_s: 9.0, amp: 0.5}\n"
                          "excitation: {type: impulse}\nlevel: {normalize: none}\n";
  auto with = [&](const std::string& f) { return std::string(set).replace(set.find("FREQ"), 4, f); };
  dir.write("sets/one.yaml", with("440.0"));
  dir.write("sets/two.yaml", with("660.0"));
  return dir.write("study.yaml",
                   "study: webtest\ntitle: Web test\nsample_rate: 44100\nseed: 11\n"
                   "stimuli:\n"
                   "  zetaref: {paramset: sets/one.yaml}\n"
                   "  zetatwo: {paramset: sets/two.yaml}\n"
                   "  zetaquiet: {paramset: sets/one.yaml, set: {amp_scale: 0.5}}\n"
                   "  zetalow: {derive: zetaref, lowpass_hz: 3500}\n"
                   "blocks:\n"
                   "  - {type: instructions, id: hello, text: Listen.}\n"
                   "  - {type: ab, id: abx, mode: abx, pairs: [[zetaref, zetatwo]]}\n"
                   "  - {type: mushra, id: mu, reference: zetaref, conditions: [zetaquiet, zetalow]}\n"
                   "  - {type: identify, id: id, stimuli: [zetaref, zetatwo], labels: [one, two]}\n");
}

class ServeTest : public ::testing::Test {
 protected:
  void SetUp() override { start(); }
  void TearDown() override { stop(); }

  void start() {
    web::ServeOptions o;
    o.protocol_path = protocol_;
    o.db_path = db_;
    o.participants = 2;
    o.http.port = 0;
    o.http.threads = 1;
    o.http.body_limit_bytes = 16 * 1024;
    o.rate_burst = rate_burst_;
    o.rate_per_second = rate_per_second_;
    server_ = std::make_unique<web::StudyServer>(o);
    thread_ = std::thread([this] { server_->run(); });
  }
  void stop() {
    if (!server_) return;
    server_->stop();
    thread_.join();
    server_.reset();
  }
  void restart() { stop(); start(); }

  unsigned short port() const { return server_->port(); }
  std::string token(std::size_t i = 0) const { return server_->links().at(i).token; }
  std::string api(const std::string& what, std::size_t i = 0) const { return "/api/" + token(i) + "/" + what; }
  HttpReply get(const std::string& target) const { return http_call(port(), "GET", target); }
  HttpReply post(const std::string& target, const nlohmann::json& body) const { return http_call(port(), "POST", target, body.dump()); }

  nlohmann::json page(std::size_t i = 0) const { return nlohmann::json::parse(get(api("trial", i)).body).at("page"); }

  // Plays every sound of `page`, as the client reports it.
  void hear_all(const nlohmann::json& page, std::size_t i = 0) const {
    for (const auto& s : page.at("sounds"))
      EXPECT_EQ(post(api("event", i), {{"trial", page["trial"]}, {"step", page["step"]}, {"kind", "play"}, {"sound", s["id"]}}).status, 200);
  }

  // A valid answer to the page, as the client would send it.
  static nlohmann::json answer_body(const nlohmann::json& page) { return test::answer_body(page); }

  // Hears and answers the current trial; returns the reply.
  HttpReply answer_current(std::size_t i = 0) const {
    const nlohmann::json p = page(i);
    hear_all(p, i);
    return post(api("answer", i), answer_body(p));
  }

  std::int64_t stored(const std::string& table) const {
    return ResultsStore(db_, ResultsStore::Mode::read_only).count(table);
  }

  double rate_burst_ = 300, rate_per_second_ = 100;
  TempDir dir_;
  std::string protocol_ = write_web_study(dir_);
  std::string db_ = dir_.file("results.sqlite");  // a file, or a PostgreSQL URI set before SetUp
  std::unique_ptr<web::StudyServer> server_;
  std::thread thread_;
};

}  // namespace ms::test
