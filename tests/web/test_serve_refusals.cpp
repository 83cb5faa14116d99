// serve refuses what a participant's browser should never send, and the store stays as it was.
#include "web/serve_fixture.hpp"

namespace ms::test {
namespace {

TEST_F(ServeTest, AReplayedAnswerIsRefused) {
  const nlohmann::json p = page();
  const nlohmann::json body = answer_body(p);
  ASSERT_EQ(post(api("answer"), body).status, 200);
  const auto responses = stored("responses");
  const HttpReply again = post(api("answer"), body);
  EXPECT_EQ(again.status, 409);
  EXPECT_NE(again.body.find("answered already"), std::string::npos) << again.body;
  EXPECT_EQ(stored("responses"), responses);
}

TEST_F(ServeTest, AnAnswerToATrialNotYetSentIsRefused) {
  // Nothing was sent yet: not even trial 0 may be answered.
  HttpReply r = post(api("answer"), {{"trial", 0}, {"step", 0}, {"answer", "ok"}, {"rt_ms", 1}});
  EXPECT_EQ(r.status, 409);
  EXPECT_NE(r.body.find("not been sent yet"), std::string::npos) << r.body;
  const nlohmann::json p = page();
  nlohmann::json ahead = answer_body(p);
  ahead["trial"] = p["trial"].get<int>() + 1;
  r = post(api("answer"), ahead);
  EXPECT_EQ(r.status, 409);
  EXPECT_EQ(stored("responses"), 0);
}

TEST_F(ServeTest, AnAnswerBeforeListeningIsRefusedWithTheWindowsReason) {
  ASSERT_EQ(answer_current().status, 200);
  const nlohmann::json p = page();  // the ABX trial
  const HttpReply r = post(api("answer"), answer_body(p));
  EXPECT_EQ(r.status, 422);
  EXPECT_NE(r.body.find("Listen to every sound before answering (0 of 3 heard)"), std::string::npos) << r.body;
  EXPECT_EQ(stored("responses"), 1);
}

TEST_F(ServeTest, AnAnswerThatDoesNotFitItsTrialIsRefused) {
  ASSERT_EQ(answer_current().status, 200);
  const nlohmann::json p = page();
  hear_all(p);
  nlohmann::json body = answer_body(p);
  body["answer"] = "C";
  EXPECT_EQ(post(api("answer"), body).status, 422);
  body["answer"] = "A";
  body["rt_ms"] = -5;
  EXPECT_EQ(post(api("answer"), body).status, 400);
  EXPECT_EQ(stored("responses"), 1);
}

TEST_F(ServeTest, MalformedJsonIsRefusedWithItsLocation) {
  page();
  const HttpReply r = http_call(port(), "POST", api("answer"), "{\"trial\": 0,, \"answer\": \"ok\"}");
  EXPECT_EQ(r.status, 400);
  EXPECT_NE(r.body.find("request body: line 1, column 13"), std::string::npos) << r.body;
  EXPECT_EQ(http_call(port(), "POST", api("answer"), "[1, 2]").status, 400);  // not an object
  const HttpReply missing = post(api("answer"), {{"trial", 0}});
  EXPECT_EQ(missing.status, 400);
  EXPECT_NE(missing.body.find("'rt_ms'"), std::string::npos) << missing.body;
  EXPECT_EQ(stored("responses"), 0);
}

TEST_F(ServeTest, AnOversizedBodyIsRefusedUnread) {
  page();
  nlohmann::json body{{"trial", 0}, {"step", 0}, {"answer", "ok"}, {"rt_ms", 1}, {"padding", std::string(40000, 'x')}};
  const HttpReply r = post(api("answer"), body);
  EXPECT_EQ(r.status, 413);
  EXPECT_EQ(stored("responses"), 0);
}

TEST_F(ServeTest, NoPathFromARequestReachesTheFileSystem) {
  for (const std::string target : {"/client/../../../../etc/passwd", "/client/%2e%2e/%2e%2e/etc/passwd",
                                   "/client/../study.yaml", "/client//etc/passwd", "/client/index.html/../../study.yaml",
                                   "/study.yaml", "/results.sqlite", "/etc/passwd"}) {
    const HttpReply r = get(target);
    EXPECT_EQ(r.status, 404) << target;
    EXPECT_EQ(r.body.find("root:"), std::string::npos) << target;
    EXPECT_EQ(r.body.find("webtest"), std::string::npos) << target;
  }
  for (const std::string id : {std::string("../../study"), std::string("..%2f..%2fstudy"), std::string(32, '0')})
    EXPECT_EQ(get(api("sound/" + id)).status, 404) << id;
  const std::string raw = raw_exchange(port(), "GET ../../etc/passwd HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n", false);
  EXPECT_EQ(raw.find("root:"), std::string::npos);
  EXPECT_EQ(get("/client/app.js").status, 200);  // the client's own files are served
}

TEST_F(ServeTest, ADroppedConnectionMidAnswerStoresNothingAndTheAnswerCanBeSentAgain) {
  const nlohmann::json p = page();
  const std::string body = answer_body(p).dump();
  const std::string head = "POST " + api("answer") + " HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n"
                           "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n";
  raw_exchange(port(), head + body.substr(0, body.size() / 2), true);  // the browser went away mid-body
  EXPECT_EQ(stored("responses"), 0);
  EXPECT_EQ(page()["trial"], p["trial"]);
  EXPECT_EQ(post(api("answer"), answer_body(p)).status, 200);
  EXPECT_EQ(stored("responses"), 1);
}

TEST_F(ServeTest, OneParticipantsLinkCannotAnswerForAnother) {
  const nlohmann::json first = page(0);
  page(1);
  const HttpReply r = post(api("answer", 1), answer_body(first));  // same trial number, other link
  EXPECT_EQ(r.status, 200);  // participant 2 answered its own trial 0
  ResultsStore store(dir_.file("results.sqlite"), ResultsStore::Mode::read_only);
  const auto rows = store.response_rows();
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].participant_code, "web-002");
  EXPECT_EQ(post(api("answer", 1), answer_body(first)).status, 409);
}

TEST_F(ServeTest, ALinkHammeredBeyondItsRateIsToldToWait) {
  rate_burst_ = 6;
  rate_per_second_ = 0.01;  // no refill within the test
  restart();
  const nlohmann::json p = page();  // 1 request
  for (int i = 0; i < 5; ++i) EXPECT_EQ(get(api("trial")).status, 200);
  const HttpReply refused = post(api("answer"), answer_body(p));
  EXPECT_EQ(refused.status, 429);
  EXPECT_NE(refused.body.find("too many requests"), std::string::npos);
  EXPECT_EQ(stored("responses"), 0);
  EXPECT_EQ(get("/client/app.js").status, 200);  // the client's files are not counted
  EXPECT_EQ(get(api("trial", 1)).status, 200);   // nor is another link's bucket touched
}

}  // namespace
}  // namespace ms::test
