// CSV files as other programs write them, read by the commands that take CSV; and what the commands
// write, neutralised against formula injection.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "synthesis/tidy_csv.hpp"
#include "support/test_util.hpp"

using namespace ms;

namespace {

const std::string kCsv = std::string(MODALSTUDY_TEST_DATA) + "/csv/";

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

}  // namespace

TEST(CliCsvFiles, PruneReadsAPandasModesFileWithBomAndQuotes) {
  test::TempDir dir;
  const auto r = test::run_cli("prune " + kCsv + "modes_pandas_bom_quoted.csv --method energy -o " + dir.file("o.csv"), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const TidyCsv out = TidyCsv::read(dir.file("o.csv"));
  ASSERT_EQ(out.rows(), 3u);
  EXPECT_EQ(out.number(1, out.column("freq_hz")), 1234.5);
}

TEST(CliCsvFiles, MdsOutputNeutralisesFormulaLabels) {
  test::TempDir dir;
  const std::string m = dir.write("m.csv", ",=cmd,b,-c\n=cmd,0,1,2\nb,1,0,3\n-c,2,3,0\n");
  const auto r = test::run_cli("stats mds " + m + " --dims 1 -o " + dir.file("p.csv"), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string text = slurp(dir.file("p.csv"));
  EXPECT_EQ(text.rfind("label,dim1\r\n", 0), 0u) << text;
  EXPECT_NE(text.find("\r\n\"'=cmd\","), std::string::npos) << text;
  EXPECT_NE(text.find("\r\n\"'-c\","), std::string::npos) << text;
  EXPECT_EQ(text.find("\r\n=cmd"), std::string::npos) << text;
}
