// serve's experimenter page: its own token, completion as the store has it, the export as downloads.
#include <filesystem>

#include "studyapp/core/export.hpp"
#include "studyapp/web/web_routes.hpp"
#include "studyapp/web/web_token.hpp"
#include "synthesis/bounded_file.hpp"
#include "web/serve_fixture.hpp"

namespace ms::test {
namespace {

class ExperimenterPageTest : public ServeTest {
 protected:
  std::string xapi(const std::string& what) const { return "/xapi/" + server_->experimenter_token() + "/" + what; }
  nlohmann::json completion() const {
    const HttpReply r = get(xapi("completion"));
    EXPECT_EQ(r.status, 200) << r.body;
    return nlohmann::json::parse(r.body);
  }
};

TEST_F(ExperimenterPageTest, HasItsOwn128BitTokenNeverAParticipants) {
  const std::string& t = server_->experimenter_token();
  EXPECT_EQ(t.size(), 32u);
  EXPECT_TRUE(web::token_shaped(t));
  for (const auto& link : server_->links()) EXPECT_NE(link.token, t);
  EXPECT_EQ(server_->experimenter_url("http://h:1/"), "http://h:1/x/" + t);
  const HttpReply page = get("/x/" + t);
  EXPECT_EQ(page.status, 200);
  EXPECT_NE(page.body.find("/client/experimenter.js"), std::string::npos);
  const std::string first = t;
  restart();
  EXPECT_NE(server_->experimenter_token(), first);  // drawn afresh at every start
  EXPECT_EQ(get("/x/" + first).status, 404);
}

TEST_F(ExperimenterPageTest, IsRefusedWithoutTheToken) {
  const std::string t = server_->experimenter_token();
  for (const std::string& wrong : {token(0), std::string(32, '0'), t.substr(0, 31), t + "0", std::string("experimenter")}) {
    EXPECT_EQ(get("/x/" + wrong).status, 404) << wrong;
    EXPECT_EQ(get("/xapi/" + wrong + "/completion").status, 404) << wrong;
    EXPECT_EQ(get("/xapi/" + wrong + "/export").status, 404) << wrong;
    EXPECT_EQ(get("/xapi/" + wrong + "/export/responses.csv").status, 404) << wrong;
  }
  EXPECT_EQ(get("/xapi/completion").status, 404);
  // Nor does the experimenter's token open a participant's pages.
  EXPECT_EQ(get("/s/" + t).status, 404);
  EXPECT_EQ(get("/api/" + t + "/trial").status, 404);
  EXPECT_EQ(post(xapi("completion"), nlohmann::json::object()).status, 405);
}

TEST_F(ExperimenterPageTest, CompletionMatchesTheStore) {
  nlohmann::json c = completion();
  ASSERT_EQ(c["participants"].size(), 2u);
  EXPECT_EQ(c["participants"][0]["participant"], "web-001");
  EXPECT_EQ(c["participants"][0]["state"], "not started");
  EXPECT_EQ(c["participants"][0]["answered"], 0);
  EXPECT_EQ(c["participants"][0]["scheduled"], 5);  // the schedule the session will store
  EXPECT_EQ(c["finished"], 0);

  for (int n = 0; n < 2; ++n) ASSERT_EQ(answer_current(0).status, 200);
  for (int n = 0; n < 5; ++n) ASSERT_EQ(answer_current(1).status, 200);
  c = completion();
  ResultsStore store(dir_.file("results.sqlite"), ResultsStore::Mode::read_only);
  const std::vector<SessionSummary> summaries = store.session_summaries();
  ASSERT_EQ(summaries.size(), 2u);
  for (const SessionSummary& s : summaries) {
    const nlohmann::json& row = c["participants"][s.participant_code == "web-001" ? 0 : 1];
    EXPECT_EQ(row["participant"], s.participant_code);
    EXPECT_EQ(row["answered"], s.responses);
    EXPECT_EQ(row["scheduled"], s.trials);
    EXPECT_EQ(row["state"], s.finished_ms ? "finished" : "unfinished");
    EXPECT_EQ(row["sessions"], 1);
  }
  EXPECT_EQ(c["participants"][0]["answered"], 2);
  EXPECT_EQ(c["participants"][1]["state"], "finished");
  EXPECT_EQ(c["answered"], store.count("responses"));
  EXPECT_EQ(c["finished"], 1);
}

TEST_F(ExperimenterPageTest, DownloadsAreTheFilesModalstudyExportWrites) {
  EXPECT_EQ(get(xapi("export/responses.csv")).status, 409);  // nothing stored yet
  EXPECT_EQ(nlohmann::json::parse(get(xapi("export")).body)["files"].size(), 0u);
  for (int n = 0; n < 5; ++n) ASSERT_EQ(answer_current(0).status, 200);
  const nlohmann::json list = nlohmann::json::parse(get(xapi("export")).body);
  EXPECT_EQ(list["responses"], 5);
  const ExportSummary direct = export_results(dir_.file("results.sqlite"), dir_.file("direct"));
  std::vector<std::string> expected{"responses.csv", "study.json", "trials.csv", "events.csv"};
  expected.insert(expected.end(), direct.tables.begin(), direct.tables.end());
  EXPECT_EQ(list["files"].get<std::vector<std::string>>(), expected);
  for (const std::string name : {"responses.csv", "trials.csv", "events.csv", "mushra.csv"}) {
    const HttpReply r = get(xapi("export/" + name));
    ASSERT_EQ(r.status, 200) << name << ": " << r.body;
    EXPECT_EQ(r.content_type, "text/csv; charset=utf-8");
    EXPECT_EQ(r.body, read_bounded_file(dir_.file("direct/" + name), kCsvFileLimit)) << name;
  }
  EXPECT_EQ(get(xapi("export/nothing.csv")).status, 404);
  EXPECT_EQ(get(xapi("export/..%2Fresults.sqlite")).status, 404);
  EXPECT_EQ(get(xapi("export/results.sqlite")).status, 404);
}

TEST_F(ExperimenterPageTest, TheLogNamesNeitherTokenNorFile) {
  const std::string t = server_->experimenter_token();
  EXPECT_EQ(web::loggable_target({"GET", "/x/" + t, ""}), "GET /x/*");
  EXPECT_EQ(web::loggable_target({"GET", "/xapi/" + t + "/export/responses.csv", ""}), "GET /xapi/*/export/*");
}

}  // namespace
}  // namespace ms::test
