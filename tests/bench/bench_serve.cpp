// Load on one `modalstudy serve` process over loopback: N simulated participants at once (default 200),
// each on its own keep-alive connection, walking a whole session as fast as the server allows (every
// sound fetched, every play reported, then the answer). Bounded and self-stopping: each session has a
// fixed number of trials, and the run gives up after --limit-s. Reports the latency of a committed
// answer (POST answer to its reply, which carries the next trial) at p50/p99, answers per second, the
// server's peak RSS (VmHWM), and checks the store afterwards: one finished session per participant,
// every scheduled trial answered exactly once.
//   bench_serve [--participants 200] [--db FILE|postgresql://...] [--limit-s 300] [--bin modalstudy]
// The database defaults to $MODALSTUDY_BENCH_DIR or the current folder (not /tmp: tmpfs hides fsync);
// $MODALSTUDY_TEST_POSTGRES_URL, when set and no --db is given, is used instead.
#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <nlohmann/json.hpp>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <mutex>
#include <regex>
#include <set>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "../web/answer_body.hpp"
#include "studyapp/core/results_store.hpp"

namespace {

namespace fs = std::filesystem;
namespace beast = boost::beast;
namespace http = beast::http;
namespace net = boost::asio;
using tcp = net::ip::tcp;
using Clock = std::chrono::steady_clock;

constexpr int kIdentifyRepeats = 10;  // 20 identify trials, 2 ABX, 1 MUSHRA, 1 instructions: 24 per session

// A study id of its own for every run, so runs on one PostgreSQL database never meet.
std::string write_study(const fs::path& dir, const std::string& study) {
  fs::create_directories(dir / "sets");
  const std::string set = "sample_rate: 44100\nduration_s: 0.3\nmodes:\n  - {freq_hz: FREQ, decay_per_s: 9.0, amp: 0.5}\n"
                          "excitation: {type: impulse}\nlevel: {normalize: none}\n";
  for (const auto& [name, freq] : {std::pair{"one", "440.0"}, {"two", "660.0"}})
    std::ofstream(dir / "sets" / (std::string(name) + ".yaml")) << std::regex_replace(set, std::regex("FREQ"), freq);
  const fs::path protocol = dir / "load.yaml";
  std::ofstream(protocol) << "study: " << study << "\ntitle: Load\nsample_rate: 44100\nseed: 5\nstimuli:\n"
                             "  one: {paramset: sets/one.yaml}\n  two: {paramset: sets/two.yaml}\n"
                             "  quiet: {paramset: sets/one.yaml, set: {amp_scale: 0.5}}\n"
                             "blocks:\n  - {type: instructions, id: hello, text: Listen.}\n"
                             "  - {type: ab, id: abx, mode: abx, pairs: [[one, two]], repeats: 2}\n"
                             "  - {type: mushra, id: mu, reference: one, conditions: [quiet, two]}\n"
                             "  - {type: identify, id: id, stimuli: [one, two], labels: [one, two], repeats: "
                          << kIdentifyRepeats << "}\n";
  return protocol.string();
}

// `modalstudy serve` as a child process; its links and port read from what it prints.
struct ServeProcess {
  pid_t pid = -1;
  unsigned short port = 0;
  std::vector<std::string> tokens;

  ServeProcess(const std::string& bin, const std::vector<std::string>& args, std::size_t participants) {
    int out[2];
    if (::pipe(out) != 0) throw std::runtime_error("pipe failed");
    pid = ::fork();
    if (pid == 0) {
      ::dup2(out[1], 1);
      ::close(out[0]);
      std::vector<char*> argv{const_cast<char*>(bin.c_str())};
      for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
      argv.push_back(nullptr);
      ::execv(bin.c_str(), argv.data());
      std::perror("execv");
      std::_Exit(127);
    }
    ::close(out[1]);
    FILE* text = ::fdopen(out[0], "r");
    const std::regex served(R"(^serving .* at http://[0-9.]+:([0-9]+)$)"), link(R"(^web-[0-9]+ \S+/s/([0-9a-f]+)$)");
    char line[4096];
    while (tokens.size() < participants && std::fgets(line, sizeof line, text)) {
      std::string l(line);
      if (!l.empty() && l.back() == '\n') l.pop_back();
      std::smatch m;
      if (std::regex_match(l, m, served)) port = static_cast<unsigned short>(std::stoi(m[1]));
      if (std::regex_match(l, m, link)) tokens.push_back(m[1]);
    }
    // The rest of its output is not needed; a thread drains it so the server never blocks on a full pipe.
    std::thread([text] {
      char rest[4096];
      while (std::fgets(rest, sizeof rest, text)) {}
      std::fclose(text);
    }).detach();
    if (tokens.size() != participants || port == 0) throw std::runtime_error("serve printed no links (see its stderr)");
  }
  long peak_rss_kib() const {
    std::ifstream status("/proc/" + std::to_string(pid) + "/status");
    for (std::string l; std::getline(status, l);)
      if (l.rfind("VmHWM:", 0) == 0) return std::stol(l.substr(6));
    return -1;
  }
  int stop() {
    ::kill(pid, SIGINT);
    int status = 0;
    ::waitpid(pid, &status, 0);
    return status;
  }
};

// One participant's keep-alive connection.
class Connection {
 public:
  explicit Connection(unsigned short port) : port_(port) { connect(); }

  std::pair<int, std::string> call(http::verb method, const std::string& target, const std::string& body = "") {
    for (int attempt = 0;; ++attempt) {
      http::request<http::string_body> req{method, target, 11};
      req.set(http::field::host, "127.0.0.1");
      req.keep_alive(true);
      if (!body.empty()) req.set(http::field::content_type, "application/json");
      req.body() = body;
      req.prepare_payload();
      beast::error_code ec;
      http::write(stream_, req, ec);
      http::response<http::string_body> res;
      if (!ec) http::read(stream_, buffer_, res, ec);
      if (!ec) {
        if (!res.keep_alive()) connect();
        return {res.result_int(), res.body()};
      }
      if (attempt == 2) throw std::runtime_error("request failed: " + ec.message());
      connect();
    }
  }

 private:
  void connect() {
    beast::error_code ignored;
    stream_.socket().close(ignored);
    stream_.connect(tcp::endpoint(net::ip::make_address("127.0.0.1"), port_));
    buffer_.clear();
  }
  unsigned short port_;
  net::io_context ioc_;
  beast::tcp_stream stream_{ioc_};
  beast::flat_buffer buffer_;
};

struct Tally {
  std::mutex mutex;
  std::vector<double> answer_ms;
  std::atomic<long> answers{0}, throttled{0}, refused{0};
  std::atomic<bool> give_up{false};
  std::vector<std::string> failures;
};

// Walks one whole session; 429s are waited out (that is the server's allowed pace).
void participant(unsigned short port, const std::string& token, Tally& tally) {
  try {
    Connection c(port);
    const std::string api = "/api/" + token + "/";
    auto call = [&](http::verb verb, const std::string& what, const std::string& body = "") {
      for (;;) {
        auto r = c.call(verb, api + what, body);
        if (r.first != 429) return r;
        ++tally.throttled;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
      }
    };
    const auto [first_status, first_body] = call(http::verb::get, "trial");
    if (first_status != 200) throw std::runtime_error("first trial refused (" + std::to_string(first_status) + "): " + first_body);
    nlohmann::json page = nlohmann::json::parse(first_body).at("page");
    while (!page.value("finished", false) && !tally.give_up) {
      for (const auto& s : page["sounds"]) {
        call(http::verb::get, "sound/" + s["id"].get<std::string>());
        call(http::verb::post, "event",
             nlohmann::json{{"trial", page["trial"]}, {"step", page["step"]}, {"kind", "play"}, {"sound", s["id"]}}.dump());
      }
      const auto start = Clock::now();
      const auto [status, body] = call(http::verb::post, "answer", ms::test::answer_body(page).dump());
      const double ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
      if (status != 200) {
        ++tally.refused;
        throw std::runtime_error("answer refused (" + std::to_string(status) + "): " + body);
      }
      ++tally.answers;
      {
        const std::lock_guard<std::mutex> lock(tally.mutex);
        tally.answer_ms.push_back(ms);
      }
      page = nlohmann::json::parse(body).at("page");
    }
  } catch (const std::exception& e) {
    const std::lock_guard<std::mutex> lock(tally.mutex);
    tally.failures.push_back(e.what());
  }
}

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(p * static_cast<double>(v.size())))];
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t participants = 200;
  std::string db, bin;
  double limit_s = 300;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--participants") participants = std::stoul(value);
    else if (key == "--db") db = value;
    else if (key == "--limit-s") limit_s = std::stod(value);
    else if (key == "--bin") bin = value;
    else {
      std::cerr << "bench_serve: unknown option " << key << "\n";
      return 2;
    }
  }
  const char* bench_dir = std::getenv("MODALSTUDY_BENCH_DIR");
  const fs::path work = fs::absolute(bench_dir ? bench_dir : ".") / ("bench_serve_" + std::to_string(::getpid()));
  fs::create_directories(work);
  if (db.empty()) db = std::getenv("MODALSTUDY_TEST_POSTGRES_URL") ? std::getenv("MODALSTUDY_TEST_POSTGRES_URL")
                                                                    : (work / "load.sqlite").string();
  if (bin.empty()) bin = (fs::read_symlink("/proc/self/exe").parent_path() / "modalstudy").string();
  const std::string study = "load-" + std::to_string(::getpid()) + "-" +
                            std::to_string(std::chrono::system_clock::now().time_since_epoch().count());
  const std::string protocol = write_study(work, study);

  ServeProcess serve(bin, {"serve", protocol, "--db", db, "--port", "0", "--participants", std::to_string(participants),
                           "--cache", (work / "cache").string(), "--quiet"},
                     participants);
  Tally tally;
  const auto start = Clock::now();
  std::vector<std::thread> people;
  for (const std::string& token : serve.tokens) people.emplace_back(participant, serve.port, token, std::ref(tally));
  std::thread watchdog([&] {
    while (!tally.give_up && std::chrono::duration<double>(Clock::now() - start).count() < limit_s)
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    tally.give_up = true;
  });
  for (std::thread& t : people) t.join();
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  const bool timed_out = seconds >= limit_s;
  tally.give_up = true;
  watchdog.join();
  const long rss_kib = serve.peak_rss_kib();
  serve.stop();

  // The store: one finished session per participant, each scheduled trial answered once.
  const ms::ResultsStore store(db, ms::ResultsStore::Mode::read_only);
  std::size_t sessions = 0, finished = 0, scheduled = 0;
  for (const ms::SessionSummary& s : store.session_summaries()) {
    if (s.study != study) continue;
    ++sessions;
    finished += s.finished_ms.has_value();
    scheduled += static_cast<std::size_t>(s.trials);
  }
  std::set<std::tuple<std::int64_t, int, int>> keys;
  std::size_t duplicated = 0;
  std::vector<ms::ResponseRow> rows = store.response_rows();
  std::erase_if(rows, [&](const ms::ResponseRow& r) { return r.study != study; });
  for (const ms::ResponseRow& r : rows) duplicated += !keys.emplace(r.session, r.block_index, r.trial_index).second;
  const long committed = tally.answers.load();
  const long lost = committed - static_cast<long>(rows.size());

  std::printf("bench_serve: %zu participants at once against one serve process (%s), %.1f s\n", participants,
              db.rfind("postgres", 0) == 0 ? "PostgreSQL" : "SQLite", seconds);
  std::printf("  answers committed: %ld (%.0f per second); latency of a committed answer p50 %.1f ms, p99 %.1f ms, max %.1f ms\n",
              committed, static_cast<double>(committed) / seconds, percentile(tally.answer_ms, 0.5),
              percentile(tally.answer_ms, 0.99), percentile(tally.answer_ms, 1.0));
  std::printf("  throttled requests (429, waited out): %ld; server peak RSS %.1f MiB\n", tally.throttled.load(),
              static_cast<double>(rss_kib) / 1024.0);
  std::printf("  store: %zu sessions, %zu finished, %zu responses of %zu scheduled trials; %ld lost, %zu duplicated\n",
              sessions, finished, rows.size(), scheduled, lost, duplicated);
  for (const std::string& f : tally.failures) std::printf("  participant failed: %s\n", f.c_str());
  const bool ok = !timed_out && tally.failures.empty() && sessions == participants && finished == participants &&
                  rows.size() == scheduled && lost == 0 && duplicated == 0;
  fs::remove_all(work);
  if (timed_out) std::printf("  gave up after --limit-s %.0f s\n", limit_s);
  std::printf("%s\n", ok ? "OK" : "FAILED");
  return ok ? 0 : 1;
}
