// The one CSV reader and writer (synthesis/csv.hpp) and the modes CSV read through it.
#include <gtest/gtest.h>

#include "synthesis/csv.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/modes_csv.hpp"

namespace {

using ms::csv::Record;

std::vector<std::vector<std::string>> cells(const std::vector<Record>& records) {
  std::vector<std::vector<std::string>> out;
  for (const auto& r : records) out.push_back(r.cells);
  return out;
}

using Table = std::vector<std::vector<std::string>>;

}  // namespace

TEST(Csv, BomCrlfQuotesAndPositions) {
  const auto r = ms::csv::parse("\xEF\xBB\xBF\"name\",value\r\n\"a, b\",\"say \"\"hi\"\"\"\r\n  x  ,\"two\r\nlines\"\r\n",
                                "f.csv");
  EXPECT_EQ(cells(r), (Table{{"name", "value"}, {"a, b", "say \"hi\""}, {"x", "two\r\nlines"}}));
  // The BOM is not part of the first cell's column; positions are 1-based lines and byte columns.
  EXPECT_EQ(r[0].where[0].line, 1);
  EXPECT_EQ(r[0].where[0].column, 1);
  EXPECT_EQ(r[1].where[1].line, 2);
  EXPECT_EQ(r[1].where[1].column, 8);
  EXPECT_EQ(r[2].where[1].line, 3);
  EXPECT_EQ(r[2].where[1].column, 7);
  EXPECT_EQ(r[2].where[0].file, "f.csv");
}

TEST(Csv, LineEndsBlankAndCommentLinesAndLastLine) {
  // LF, lone CR (old spreadsheets) and CRLF; a blank and a '#' line skipped; no final line end.
  const auto r = ms::csv::parse("a,b\n1,2\r3,4\r\n\n# note, not data\n5,\"6\"", "f.csv");
  EXPECT_EQ(cells(r), (Table{{"a", "b"}, {"1", "2"}, {"3", "4"}, {"5", "6"}}));
  EXPECT_EQ(r[3].where[0].line, 6);
  // Empty cells stay empty, including a trailing one.
  EXPECT_EQ(cells(ms::csv::parse(",x,\n", "e.csv")), (Table{{"", "x", ""}}));
}

TEST(Csv, BadQuotesNameLineAndColumn) {
  try {
    ms::csv::parse("a,b\n1,\"open\n2,3\n", "q.csv");
    FAIL() << "an unterminated quote was accepted";
  } catch (const ms::InputError& e) {
    EXPECT_EQ(std::string(e.what()), "q.csv:2:3: unterminated quoted field");
  }
  try {
    ms::csv::parse("a,b\n\"x\"y,2\n", "t.csv");
    FAIL() << "text after a closing quote was accepted";
  } catch (const ms::InputError& e) {
    EXPECT_EQ(std::string(e.what()), "t.csv:2:4: unexpected character after closing quote");
  }
  EXPECT_THROW(ms::csv::read_file("/nonexistent/x.csv"), ms::InputError);
}

TEST(Csv, WriterQuotesPerRfc4180) {
  EXPECT_EQ(ms::csv::field("plain"), "plain");
  EXPECT_EQ(ms::csv::field(""), "");
  EXPECT_EQ(ms::csv::field("a,b"), "\"a,b\"");
  EXPECT_EQ(ms::csv::field("say \"x\""), "\"say \"\"x\"\"\"");
  EXPECT_EQ(ms::csv::field("two\nlines"), "\"two\nlines\"");
  EXPECT_EQ(ms::csv::field("# not a comment"), "\"# not a comment\"");
  EXPECT_EQ(ms::csv::field(" padded "), "\" padded \"");
  EXPECT_EQ(ms::csv::line({"a", "b,c", ""}), "a,\"b,c\",\r\n");
}

TEST(Csv, WriterNeutralisesFormulasButNotNumbers) {
  // OWASP: a cell starting with = + - @ TAB or CR gets a leading single quote (and is quoted).
  EXPECT_EQ(ms::csv::field("=1+2"), "\"'=1+2\"");
  EXPECT_EQ(ms::csv::field("=HYPERLINK(\"http://x\",\"y\")"), "\"'=HYPERLINK(\"\"http://x\"\",\"\"y\"\")\"");
  EXPECT_EQ(ms::csv::field("+cmd|' /C calc'!A0"), "\"'+cmd|' /C calc'!A0\"");
  EXPECT_EQ(ms::csv::field("-2+3"), "\"'-2+3\"");
  EXPECT_EQ(ms::csv::field("@SUM(A1)"), "\"'@SUM(A1)\"");
  EXPECT_EQ(ms::csv::field("\t=1"), "\"'\t=1\"");
  EXPECT_EQ(ms::csv::field("\r=1"), "\"'\r=1\"");
  EXPECT_EQ(ms::csv::field("-"), "\"'-\"");
  EXPECT_EQ(ms::csv::field("-inf"), "\"'-inf\"");
  // A cell that is entirely a decimal number is data, not a formula: written as it is.
  for (const char* n : {"-3", "+1.5e-3", "-0.25", "-.5", "+7", "-1E+300", "3"}) EXPECT_EQ(ms::csv::field(n), n) << n;
  EXPECT_TRUE(ms::csv::is_number("-3"));
  EXPECT_FALSE(ms::csv::is_number("-3-"));
  EXPECT_FALSE(ms::csv::is_number("1e"));
  EXPECT_FALSE(ms::csv::is_number("."));
  EXPECT_FALSE(ms::csv::is_number("0x10"));
  EXPECT_FALSE(ms::csv::is_number("nan"));
}

TEST(Csv, WrittenCellsReadBack) {
  const std::vector<std::string> row{"a, b", "say \"x\"", "two\r\nlines", " pad ", "#1", "-3", "=1+2", ""};
  const auto r = ms::csv::parse(ms::csv::line(row) + ms::csv::line(row), "w.csv");
  ASSERT_EQ(r.size(), 2u);
  std::vector<std::string> expected = row;
  expected[6] = "'=1+2";  // neutralised
  EXPECT_EQ(r[0].cells, expected);
  EXPECT_EQ(r[1].cells, expected);
  EXPECT_EQ(r[1].where[0].line, 3);  // the quoted CRLF inside the first row counts as a line
}

TEST(Csv, NumbersInShortestForm) {
  EXPECT_EQ(ms::csv::number(0.1), "0.1");
  EXPECT_EQ(ms::csv::number(3.0), "3");
  EXPECT_EQ(ms::csv::number(-2.5e-7), "-2.5e-07");
  EXPECT_EQ(std::stod(ms::csv::number(1.0 / 3.0)), 1.0 / 3.0);
}

TEST(ModesCsv, AcceptsBomQuotedFieldsAndCrlf) {
  // What a spreadsheet or pandas with quoting=csv.QUOTE_ALL writes.
  const auto m = ms::parse_modes_csv("\xEF\xBB\xBF\"freq_hz\",\"decay_per_s\",\"amp\",\"note\"\r\n"
                                     "\"440\",\"6\",\"0.5\",\"a, quoted note\"\r\n"
                                     "880,+12,0.25,\r\n",
                                     "m.csv");
  ASSERT_EQ(m.modes.size(), 2u);
  EXPECT_EQ(m.modes[0].freq_hz, 440.0);
  EXPECT_EQ(m.modes[0].amp, 0.5);
  EXPECT_EQ(m.modes[1].decay_per_s, 12.0);
}

TEST(ModesCsv, BadCellNamesLineAndColumn) {
  try {
    ms::parse_modes_csv("freq_hz,decay_per_s,amp\n440,6,0.5\n\"880\",x,1\n", "m.csv");
    FAIL() << "a non-number was accepted";
  } catch (const ms::InputError& e) {
    EXPECT_EQ(std::string(e.what()), "m.csv:3:7: decay_per_s: expected a number, got 'x'");
  }
}
