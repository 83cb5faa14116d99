// modalstudy export: a database built through the library is exported and every cell of
// responses.csv checked; the CSV feeds `stats confusion` directly; bad input exits 2, writes nothing.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>

#include "synthesis/tidy_csv.hpp"
#include "studyapp/core/export.hpp"
#include "synthesis/csv.hpp"
#include "studyapp/core/results_store.hpp"
#include "support/test_util.hpp"

namespace ms {
namespace {

namespace fs = std::filesystem;

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

constexpr std::int64_t kT0 = 1'700'000'000'000;  // 2023-11-14T22:13:20.000Z

// Two blocks: an identification with a label answer, a MUSHRA page with a structured answer whose
// JSON holds commas and quotes (so the CSV must quote it), and a participant code with a comma.
std::string build_db(const test::TempDir& dir, bool export_personal) {
  const std::string path = dir.file("results.sqlite");
  ResultsStore store(path);
  store.add_study({"vase", "Vase, pruned", std::string(64, 'c'), "study: vase\n", export_personal});
  const auto p = store.add_participant("vase", "Doe, Jane", kT0);
  const auto s = store.start_session(p, kT0, 7u);
  store.record_trials(s, {{0, "id1", "identify", 0, {"metal"}, {"h1"}},
                          {0, "id1", "identify", 1, {"glass"}, {"h2"}},
                          {1, "m1", "mushra", 0, {"full", "e16", "lp35"}, {"h3", "h4", "h5"}}});
  store.record_response(s, {{0, 0}, "\"metal\"", 812.5, 2, kT0 + 1500});
  store.record_response(s, {{0, 1}, "\"wood\"", 1033.0, 1, kT0 + 2750});
  store.record_response(s, {{1, 0}, R"({"e16":80,"full":100,"lp35":"say \"hi\""})", 15000.25, 7, kT0 + 20001});
  store.record_event(s, {{0, 0}, EventKind::play, "metal", kT0 + 100});
  return path;
}

TEST(ExportCli, EveryCellOfResponsesCsv) {
  test::TempDir dir;
  const std::string db = build_db(dir, false);
  const auto run = test::run_cli("export " + db + " -o " + dir.file("out"), dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  // The MUSHRA answer holds a text where a score belongs: kept verbatim in responses.csv, left out of
  // mushra.csv, and said so.
  EXPECT_NE(run.err.find("notice: " + db + ": session 1, block 'm1', trial 0: answer not in mushra.csv"),
            std::string::npos) << run.err;
  const std::string csv_path = dir.file("out/responses.csv");
  const TidyCsv csv = TidyCsv::read(csv_path);
  const std::vector<std::string> header{"study",   "participant", "session", "autopilot", "block", "block_type",
                                        "trial",   "stimuli",     "response", "rt_ms",    "plays", "timestamp"};
  EXPECT_EQ(csv.header(), header);
  const std::vector<std::vector<std::string>> expected{
      {"vase", "p1", "1", "0", "id1", "identify", "0", "metal", "metal", "812.5", "2", "2023-11-14T22:13:21.500Z"},
      {"vase", "p1", "1", "0", "id1", "identify", "1", "glass", "wood", "1033.0", "1", "2023-11-14T22:13:22.750Z"},
      {"vase", "p1", "1", "0", "m1", "mushra", "0", "full;e16;lp35", R"({"e16":80,"full":100,"lp35":"say \"hi\""})",
       "15000.25", "7", "2023-11-14T22:13:40.001Z"}};
  ASSERT_EQ(csv.rows(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i)
    for (std::size_t c = 0; c < header.size(); ++c)
      EXPECT_EQ(csv.cell(i, c), expected[i][c]) << "row " << i << " column " << header[c];
  // RFC 4180 on the wire: CRLF, quotes doubled inside a quoted field; no personal code anywhere.
  const std::string text = slurp(csv_path);
  EXPECT_NE(text.find(R"("{""e16"":80,""full"":100,""lp35"":""say \""hi\""""}")"), std::string::npos) << text;
  EXPECT_EQ(text.find("Doe"), std::string::npos);
  EXPECT_EQ(text.substr(0, text.find('\n') + 1),
            "study,participant,session,autopilot,block,block_type,trial,stimuli,response,rt_ms,plays,timestamp\r\n");

  const auto meta = nlohmann::json::parse(slurp(dir.file("out/study.json")));
  EXPECT_EQ(meta["studies"][0]["id"], "vase");
  EXPECT_EQ(meta["studies"][0]["title"], "Vase, pruned");
  EXPECT_EQ(meta["studies"][0]["protocol_sha256"], std::string(64, 'c'));
  EXPECT_EQ(meta["studies"][0]["export_personal"], false);
  EXPECT_EQ(meta["counts"]["responses"], 3);
  EXPECT_EQ(meta["counts"]["trials"], 3);
  EXPECT_EQ(meta["counts"]["events"], 1);
  EXPECT_EQ(meta["counts"]["participants"], 1);
  EXPECT_EQ(slurp(dir.file("out/study.json")).find("Doe"), std::string::npos);
}

TEST(ExportCli, PersonalCodeOnlyWhenTheStudyAllowsIt) {
  test::TempDir dir;
  const std::string db = build_db(dir, true);
  const auto run = test::run_cli("export " + db + " -o " + dir.file("out") + " --json", dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(nlohmann::json::parse(run.out)["responses"], 3);
  const TidyCsv csv = TidyCsv::read(dir.file("out/responses.csv"));
  ASSERT_EQ(csv.rows(), 3u);
  EXPECT_EQ(csv.cell(0, csv.column("participant")), "Doe, Jane");
}

TEST(ExportCli, ExportedCsvFeedsStatsConfusion) {
  test::TempDir dir;
  const std::string db = dir.file("id.sqlite");
  {
    ResultsStore store(db);
    store.add_study({"id", "Identification", std::string(64, 'd'), "study: id\n", false});
    const auto s = store.start_session(store.add_participant("id", "x", kT0), kT0, 1u);
    const std::vector<std::pair<std::string, std::string>> pairs{
        {"metal", "metal"}, {"metal", "glass"}, {"glass", "glass"}, {"glass", "glass"}, {"wood", "wood"}};
    std::vector<TrialRecord> trials;
    for (int i = 0; i < int(pairs.size()); ++i) trials.push_back({0, "id", "identify", i, {pairs[i].first}, {"h"}});
    store.record_trials(s, trials);
    for (int i = 0; i < int(pairs.size()); ++i)
      store.record_response(s, {{0, i}, nlohmann::json(pairs[i].second).dump(), 500.0, 1, kT0 + i});
  }
  ASSERT_EQ(test::run_cli("export " + db + " -o " + dir.file("out"), dir).exit_code, 0);
  const auto run = test::run_cli(
      "stats confusion " + dir.file("out/responses.csv") + " --truth stimuli --response response --json", dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto j = nlohmann::json::parse(run.out);
  // 4 of 5 correct; labels sorted: glass, metal, wood.
  EXPECT_NEAR(j["accuracy"].get<double>(), 0.8, 1e-12) << run.out;
}

TEST(ExportCli, BadInputExitsTwoAndWritesNothing) {
  test::TempDir dir;
  const std::string not_db = dir.write("notes.sqlite", "this is not a database\n");
  for (const std::string& input : {dir.file("missing.sqlite"), not_db}) {
    const auto run = test::run_cli("export " + input + " -o " + dir.file("out"), dir);
    EXPECT_EQ(run.exit_code, 2) << input;
    EXPECT_EQ(test::count_lines(run.err), 1u) << run.err;
    EXPECT_NE(run.err.find(input), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(dir.file("out"))) << input;
  }
  EXPECT_EQ(slurp(not_db), "this is not a database\n");
  EXPECT_FALSE(fs::exists(dir.file("missing.sqlite")));
}

TEST(ExportCli, CsvFieldQuotesPerRfc4180) {
  EXPECT_EQ(ms::csv::field("plain"), "plain");
  EXPECT_EQ(ms::csv::field("a,b"), "\"a,b\"");
  EXPECT_EQ(ms::csv::field("say \"x\""), "\"say \"\"x\"\"\"");
  EXPECT_EQ(ms::csv::field("two\nlines"), "\"two\nlines\"");
  EXPECT_EQ(iso8601_utc(kT0), "2023-11-14T22:13:20.000Z");
  EXPECT_EQ(iso8601_utc(-1), "1969-12-31T23:59:59.999Z");
}

}  // namespace
}  // namespace ms
