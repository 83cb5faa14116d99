// A database the autopilot filled with the demo (tests/data/answers_v1/demo-autopilot.sqlite) exports
// to the same tables it did when it was made (the CSVs beside it): answers stored by earlier versions
// stay readable, cell for cell. (ab.csv's last four columns, the protocol's written pair and the answer
// turned to it, were added after the database was made: its rows are the earlier ones plus those.)
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "studyapp/core/export.hpp"
#include "support/test_util.hpp"

namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST(ExportStoredAnswers, ADemoDatabaseMadeEarlierExportsTheSameTables) {
  const std::string data = std::string(MODALSTUDY_SOURCE_DIR) + "/tests/data/answers_v1/";
  ms::test::TempDir dir;
  const std::string db = dir.file("demo.sqlite");
  std::filesystem::copy_file(data + "demo-autopilot.sqlite", db);
  const ms::ExportSummary s = ms::export_results(db, dir.file("export"));
  EXPECT_EQ(s.responses, 19u);
  for (const char* table : {"ab", "adjust", "identify", "magnitude", "mushra", "questionnaire", "rating", "staircase",
                            "responses", "trials"}) {
    const std::string name = std::string(table) + ".csv";
    const std::string expected = slurp(data + name);
    ASSERT_FALSE(expected.empty()) << name;
    EXPECT_EQ(slurp(dir.file("export/" + name)), expected) << name;
  }
}
