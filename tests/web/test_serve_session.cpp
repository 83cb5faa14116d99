// serve over loopback: links, a whole session, resuming, and what the page may know.
#include <sys/stat.h>

#include <filesystem>

#include "web/serve_fixture.hpp"

namespace ms::test {
namespace {

TEST_F(ServeTest, LinksCarry128BitTokensKeptPrivatelyBesideTheDatabase) {
  ASSERT_EQ(server_->links().size(), 2u);
  EXPECT_EQ(server_->links()[0].participant, "web-001");
  EXPECT_EQ(token(0).size(), 32u);  // 16 random bytes in hex
  EXPECT_NE(token(0), token(1));
  struct stat st {};
  ASSERT_EQ(::stat(server_->links_path().c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0600);
  const std::string first = token(0);
  restart();  // the same links after a restart
  EXPECT_EQ(token(0), first);
}

TEST_F(ServeTest, ALinkServesThePageAndAWrongOneNothing) {
  const HttpReply page = get("/s/" + token());
  EXPECT_EQ(page.status, 200);
  EXPECT_NE(page.body.find("/client/app.js"), std::string::npos);
  EXPECT_EQ(get("/s/" + std::string(32, 'a')).status, 404);   // well-formed, not issued
  EXPECT_EQ(get("/s/web-001").status, 404);                   // a participant id is no token
  EXPECT_EQ(get("/api/" + token().substr(0, 31) + "/trial").status, 404);
  EXPECT_EQ(get("/api/" + token() + "X/trial").status, 404);
  EXPECT_FALSE(std::filesystem::exists(dir_.file("results.sqlite")));  // no session was opened for any of them
}

TEST_F(ServeTest, AWholeSessionIsStoredAndEndsOnTheEndPage) {
  nlohmann::json p = page();
  const std::size_t total = p["total"];
  EXPECT_EQ(total, 5u);
  for (std::size_t n = 0; n < total; ++n) {
    EXPECT_EQ(stored("responses"), static_cast<std::int64_t>(n));
    const HttpReply r = answer_current();
    ASSERT_EQ(r.status, 200) << r.body;
  }
  EXPECT_EQ(stored("responses"), 5);
  EXPECT_TRUE(page().value("finished", false));
  restart();
  EXPECT_TRUE(page().value("finished", false));  // a finished link shows the end page, also later
  // MUSHRA scores were stored under the stimuli's names, mapped from the page's opaque ids.
  ResultsStore store(dir_.file("results.sqlite"), ResultsStore::Mode::read_only);
  bool saw_mushra = false;
  for (const ResponseRow& row : store.response_rows()) {
    if (row.block_type != "mushra") continue;
    saw_mushra = true;
    const auto value = nlohmann::json::parse(row.value_json);
    EXPECT_TRUE(value.contains("zetaref") && value.contains("zetaquiet") && value.contains("zetalow")) << row.value_json;
  }
  EXPECT_TRUE(saw_mushra);
}

TEST_F(ServeTest, ReloadingAndRestartingResumeAtTheFirstUnansweredTrial) {
  ASSERT_EQ(answer_current().status, 200);
  ASSERT_EQ(answer_current().status, 200);
  const nlohmann::json shown = page();
  EXPECT_EQ(shown["position"], 3);
  EXPECT_EQ(page()["sounds"], shown["sounds"]);  // a reload gets the same trial and sound ids
  restart();
  const nlohmann::json resumed = page();
  EXPECT_EQ(resumed["trial"], shown["trial"]);
  EXPECT_EQ(resumed["type"], "mushra");
  EXPECT_NE(resumed["sounds"][0]["id"], shown["sounds"][0]["id"]);  // fresh ids for every sending
  EXPECT_EQ(stored("responses"), 2);
  EXPECT_EQ(stored("sessions"), 1);  // resumed, not restarted
}

TEST_F(ServeTest, TheMushraPageNamesNoStimulusAndNoHash) {
  ASSERT_EQ(answer_current().status, 200);
  ASSERT_EQ(answer_current().status, 200);
  const HttpReply r = get(api("trial"));
  ASSERT_EQ(nlohmann::json::parse(r.body)["page"]["type"], "mushra");
  EXPECT_EQ(r.body.find("zeta"), std::string::npos) << r.body;
  for (const auto& entry : std::filesystem::directory_iterator(dir_.file("stimulus-cache")))
    EXPECT_EQ(r.body.find(entry.path().stem().string()), std::string::npos) << "a recipe hash is on the page";
  const nlohmann::json p = nlohmann::json::parse(r.body)["page"];
  ASSERT_GE(p["sounds"].size(), 4u);  // reference + hidden reference + 2 conditions (+ anchors)
  EXPECT_EQ(p["sounds"][0]["label"], "Reference");
  for (std::size_t k = 1; k < p["sounds"].size(); ++k) EXPECT_EQ(p["sounds"][k]["label"], std::string(1, char('A' + k - 1)));
  const HttpReply wav = get(api("sound/" + p["sounds"][1]["id"].get<std::string>()));
  EXPECT_EQ(wav.status, 200);
  EXPECT_EQ(wav.content_type, "audio/wav");
  EXPECT_EQ(wav.body.substr(0, 4), "RIFF");
}

TEST_F(ServeTest, PlayEventsAreStoredWithTheClientsTimes) {
  const nlohmann::json p = page();
  ASSERT_EQ(answer_current().status, 200);  // instructions: nothing to play
  const nlohmann::json ab = page();
  const auto before = stored("events");
  ASSERT_EQ(post(api("event"), {{"trial", ab["trial"]}, {"step", 0}, {"kind", "play"}, {"sound", ab["sounds"][0]["id"]},
                                {"at_ms", 1234.5}, {"position_s", 0.0}}).status, 200);
  EXPECT_EQ(stored("events"), before + 1);
  EXPECT_EQ(post(api("event"), {{"trial", ab["trial"]}, {"kind", "play"}, {"sound", std::string(32, 'f')}}).status, 404);
  EXPECT_EQ(post(api("event"), {{"trial", ab["trial"]}, {"kind", "jump"}, {"sound", ab["sounds"][0]["id"]}}).status, 400);
  EXPECT_EQ(stored("events"), before + 1);
  EXPECT_EQ(p["type"], "instructions");
}

}  // namespace
}  // namespace ms::test
