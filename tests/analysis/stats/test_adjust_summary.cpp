// The hand-tuning analysis (analysis/stats/adjust_summary.hpp) against R on tests/data/adjust/adjust.csv
// (8 listeners x 2 sections x 3 objects, times with outliers, a choice of 0 at a slider's end, one object
// with no known truth): every box number, mean, sd and log-ratio statistic of golden.csv, which
// tests/data/adjust/make_golden.R computes with quantile(type = 7), sd and log10. And the table's
// mistakes, each one located line.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <tuple>

#include "analysis/stats/adjust_summary.hpp"

namespace {

const std::string kData = std::string(MODALSTUDY_SOURCE_DIR) + "/tests/data/adjust/";

using Key = std::tuple<std::string, std::string, std::string, std::string, std::string>;  // group object key measure stat

std::map<Key, std::string> golden() {
  const ms::TidyCsv g = ms::TidyCsv::read(kData + "golden.csv");
  std::map<Key, std::string> out;
  for (std::size_t r = 0; r < g.rows(); ++r)
    out[{g.cell(r, 0), g.cell(r, 1), g.cell(r, 2), g.cell(r, 3), g.cell(r, 4)}] = g.cell(r, 5);
  return out;
}

std::string joined(const std::vector<double>& v) {
  std::string s;
  for (double x : v) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", x);
    s += (s.empty() ? "" : ";") + std::string(text);
  }
  return s;
}

void expect_box(const std::map<Key, std::string>& g, const Key& prefix, const ms::BoxSummary& b) {
  const auto at = [&](const std::string& stat) {
    Key k = prefix;
    std::get<4>(k) = stat;
    const auto it = g.find(k);
    if (it == g.end()) throw std::runtime_error("golden has no " + std::get<0>(k) + "/" + std::get<1>(k) + "/" + std::get<2>(k) + "/" + std::get<3>(k) + "/" + stat);
    return it->second;
  };
  const std::string where = std::get<0>(prefix) + " " + std::get<1>(prefix) + " " + std::get<2>(prefix) + " " + std::get<3>(prefix);
  EXPECT_EQ(double(b.n), std::stod(at("n"))) << where;
  for (const auto& [stat, v] : {std::pair{"lower_whisker", b.lower_whisker}, {"q1", b.q1}, {"median", b.median},
                                {"q3", b.q3}, {"upper_whisker", b.upper_whisker}}) {
    const double r = std::stod(at(stat));
    EXPECT_NEAR(v, r, 1e-12 * std::max(1.0, std::abs(r))) << where << " " << stat;
  }
  // Outliers as R prints them: the same values to the 17th digit (or within 1e-12 relative).
  std::vector<double> expected;
  std::stringstream ss(at("outliers"));
  for (std::string v; std::getline(ss, v, ';');) expected.push_back(std::stod(v));
  ASSERT_EQ(b.outliers.size(), expected.size()) << where << ": " << joined(b.outliers) << " vs " << at("outliers");
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_NEAR(b.outliers[i], expected[i], 1e-12 * std::max(1.0, std::abs(expected[i]))) << where;
}

ms::AdjustColumns columns() {
  ms::AdjustColumns c;
  c.object = "object";
  c.group = "section";
  c.truth = "truth";
  return c;
}

TEST(AdjustSummary, MatchesRsBoxesSpreadsAndLogRatios) {
  const auto g = golden();
  const ms::AdjustSummary s = ms::adjust_summary(ms::TidyCsv::read(kData + "adjust.csv"), columns());
  ASSERT_EQ(s.objects.size(), 6u);  // 2 sections x 3 objects
  std::size_t ratios = 0, outliers = 0;
  for (const ms::AdjustObject& o : s.objects) {
    expect_box(g, {o.group, o.object, "", "time_s", ""}, o.time_s);
    expect_box(g, {o.group, o.object, "", "plays", ""}, o.plays);
    outliers += o.time_s.outliers.size() + o.plays.outliers.size();
    EXPECT_EQ(o.parameters.size(), o.group == "three" ? 3u : 2u);
    for (const ms::AdjustParameter& p : o.parameters) {
      expect_box(g, {o.group, o.object, p.key, "chosen", ""}, p.chosen);
      EXPECT_NEAR(p.mean, std::stod(g.at({o.group, o.object, p.key, "chosen", "mean"})), 1e-12 * std::abs(p.mean));
      EXPECT_NEAR(p.sd, std::stod(g.at({o.group, o.object, p.key, "chosen", "sd"})), 1e-12 * std::abs(p.sd));
      const bool known = g.count({o.group, o.object, p.key, "log10_ratio", "n"}) > 0;
      EXPECT_EQ(p.truth.has_value(), known) << o.object << " " << p.key;
      EXPECT_EQ(p.log10_ratio.has_value(), known) << o.object << " " << p.key;
      if (!known) continue;
      ++ratios;
      expect_box(g, {o.group, o.object, p.key, "log10_ratio", ""}, *p.log10_ratio);
      EXPECT_NEAR(p.log10_ratio_mean, std::stod(g.at({o.group, o.object, p.key, "log10_ratio", "mean"})), 1e-12);
      EXPECT_NEAR(p.log10_ratio_rms, std::stod(g.at({o.group, o.object, p.key, "log10_ratio", "rms"})), 1e-12);
      EXPECT_EQ(double(p.not_positive), std::stod(g.at({o.group, o.object, p.key, "log10_ratio", "not_positive"})));
    }
  }
  EXPECT_EQ(ratios, 10u);  // porcelain and wood: 3 + 2 keys each; the cymbal's truth is NA
  EXPECT_GT(outliers, 0u);
  ASSERT_EQ(s.groups.size(), 2u);
  for (const ms::AdjustGroup& grp : s.groups) {
    expect_box(g, {grp.group, "", "", "time_s", ""}, grp.time_s);
    expect_box(g, {grp.group, "", "", "plays", ""}, grp.plays);
  }
}

// A slider left at 0 has no log ratio: it is counted, not averaged in as minus infinity.
TEST(AdjustSummary, AChoiceOfZeroIsCountedNotLogged) {
  const ms::AdjustSummary s = ms::adjust_summary(ms::TidyCsv::read(kData + "adjust.csv"), columns());
  for (const ms::AdjustObject& o : s.objects)
    for (const ms::AdjustParameter& p : o.parameters) {
      const bool zero = o.group == "two" && o.object == "wood" && p.key == "damping.alpha1";
      EXPECT_EQ(p.not_positive, zero ? 1u : 0u) << o.group << " " << o.object << " " << p.key;
      if (zero) EXPECT_EQ(p.log10_ratio->n, p.chosen.n - 1);
    }
}

std::string error_of(const std::string& csv, ms::AdjustColumns c = columns()) {
  try {
    ms::adjust_summary(ms::TidyCsv::parse(csv, "a.csv"), c);
  } catch (const ms::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(AdjustSummary, MistakesAreOneLocatedLine) {
  const std::string head = "participant,session,block,trial,object,section,key,value,plays,rt_ms,truth\n";
  const std::string ok = "p1,1,b,0,wood,two,damping.alpha1,30,12,90000,39\n";
  EXPECT_EQ(error_of(head + ok + "p1,1,b,0,wood,two,damping.alpha2,1e-7,12,91000,1.3e-7\n"),
            "a.csv:3:42: column 'rt_ms': differs from line 2 of the same answer (one answer's rows share it)");
  EXPECT_EQ(error_of(head + ok + "p1,1,b,0,wood,two,damping.alpha1,31,12,90000,39\n"),
            "a.csv:3:19: key 'damping.alpha1' appears twice in one answer");
  EXPECT_EQ(error_of(head + ok + "p2,1,b,0,wood,two,damping.alpha1,31,12,90000,40\n"),
            "a.csv:3:46: column 'truth': '40' differs from the truth of the same object and key on line 2");
  EXPECT_EQ(error_of(head + "p1,1,b,0,wood,two,damping.alpha1,thirty,12,90000,39\n"),
            "a.csv:2:34: column 'value': expected a number, got 'thirty'");
  EXPECT_EQ(error_of(head + "p1,1,b,0,wood,two,damping.alpha1,30,-1,90000,39\n"),
            "a.csv:2:37: column 'plays': must not be negative, got -1");
  EXPECT_EQ(error_of(head + "p1,1,b,0,wood,two,damping.alpha1,30,12,90000,about 40\n"),
            "a.csv:2:46: column 'truth': expected a number, got 'about 40'");
  EXPECT_EQ(error_of(head), "a.csv: no data rows");
  ms::AdjustColumns c = columns();
  c.group = "part";
  EXPECT_NE(error_of(head + ok, c).find("a.csv:1:1: missing column 'part'"), std::string::npos);
}

}  // namespace
