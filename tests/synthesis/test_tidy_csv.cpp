// The tidy CSV reader: quoting (RFC 4180), CRLF, comments, lookup by name, and error positions.
#include <gtest/gtest.h>

#include "synthesis/tidy_csv.hpp"

using namespace ms;

TEST(TidyCsv, QuotedFieldsCrlfAndComments) {
  const TidyCsv t = TidyCsv::parse(
      "# made by hand\r\nname, value ,note\r\n\"bowl, large\",1.5,\"say \"\"hi\"\"\"\r\n\r\n plate ,+2e-3,\"two\nlines\"\n",
      "t.csv");
  ASSERT_EQ(t.rows(), 2u);
  EXPECT_EQ(t.header()[1], "value");
  EXPECT_EQ(t.cell(0, t.column("name")), "bowl, large");
  EXPECT_EQ(t.cell(0, 2), "say \"hi\"");
  EXPECT_EQ(t.cell(1, 0), "plate");
  EXPECT_EQ(t.cell(1, 2), "two\nlines");
  EXPECT_DOUBLE_EQ(t.number(0, 1), 1.5);
  EXPECT_DOUBLE_EQ(t.number(1, 1), 0.002);
  // Line numbers count physical lines, including the comment and the blank line.
  EXPECT_EQ(t.where(1, 1).line, 5);
  EXPECT_EQ(t.where(1, 1).column, 9);
  EXPECT_TRUE(t.has_column("note"));
  EXPECT_FALSE(t.has_column("Note"));
}

TEST(TidyCsv, ErrorsNameFileLineColumn) {
  const TidyCsv t = TidyCsv::parse("a,b\n1,x\n2,inf\n", "e.csv");
  try {
    t.number(0, 1);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "e.csv:2:3: column 'b': expected a number, got 'x'");
  }
  EXPECT_THROW(t.number(1, 1), InputError);
  try {
    t.column("c");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "e.csv:1:1: missing column 'c' (columns are: a, b)");
  }
  EXPECT_THROW(TidyCsv::parse("a,a\n1,2\n", "d.csv"), InputError);
  EXPECT_THROW(TidyCsv::parse("a,b\n1,2,3\n", "n.csv"), InputError);
  EXPECT_THROW(TidyCsv::parse("a,b\n\"1,2\n", "q.csv"), InputError);
  EXPECT_THROW(TidyCsv::parse("", "empty.csv"), InputError);
  EXPECT_THROW(TidyCsv::read("/nonexistent/x.csv"), InputError);
}

// Files written by R's write.csv(as.matrix(eurodist)) and pandas' to_csv() (tests/data/csv/make_files.*):
// the header starts with an empty cell (the row names), pandas' second file has a BOM, CRLF and quotes.
TEST(TidyCsv, ReadsRAndPandasLabelledMatrices) {
  const std::string dir = std::string(MODALSTUDY_SOURCE_DIR) + "/tests/data/csv/";
  for (const char* file : {"eurodist_r.csv", "eurodist_pandas.csv", "eurodist_pandas_bom_quoted.csv"}) {
    const TidyCsv t = TidyCsv::read(dir + file);
    ASSERT_EQ(t.header().size(), 22u) << file;
    EXPECT_EQ(t.header()[0], "") << file;
    EXPECT_EQ(t.header()[1], "Athens") << file;
    EXPECT_EQ(t.header()[11], "Hook of Holland") << file;
    ASSERT_EQ(t.rows(), 21u) << file;
    EXPECT_EQ(t.cell(0, 0), "Athens") << file;
    EXPECT_EQ(t.number(0, 2), 3313.0) << file;  // Athens - Barcelona, km
    EXPECT_EQ(t.number(20, 1), 1991.0) << file;  // Vienna - Athens
  }
}

TEST(TidyCsv, OnlyTheFirstColumnNameMayBeEmpty) {
  EXPECT_NO_THROW(TidyCsv::parse(",a\nx,1\n", "r.csv"));
  try {
    TidyCsv::parse("a,,b\n1,2,3\n", "e.csv");
    FAIL() << "an empty column name was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "e.csv:1:3: empty column name in header");
  }
}
