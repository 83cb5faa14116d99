#include "analysis/stats/t_test.hpp"

#include <boost/math/distributions/students_t.hpp>
#include <algorithm>
#include <array>
#include <map>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ms {

namespace {

struct Moments {
  double n = 0, mean = 0, var = 0;  // var: unbiased (n - 1)
};

// Power of two bringing the largest |value| near 1: exact, and keeps squares of values like 1e300
// inside the double range (t, df and p do not depend on it).
double scale_of(const std::vector<double>& x, const std::vector<double>& y) {
  double m = 0;
  for (double v : x) m = std::max(m, std::abs(v));
  for (double v : y) m = std::max(m, std::abs(v));
  return m > 0 ? std::ldexp(1.0, std::ilogb(m)) : 1.0;
}

Moments moments(const std::vector<double>& v, double scale) {
  Moments m;
  m.n = double(v.size());
  for (double x : v) m.mean += x / scale;
  m.mean /= m.n;
  for (double x : v) m.var += (x / scale - m.mean) * (x / scale - m.mean);
  m.var /= m.n - 1;
  return m;
}

// diff and se in units of `scale`.
TTest finish(double diff, double se, double df, double conf_level, double scale) {
  if (!(se > 0)) throw std::domain_error("the data are constant (standard error 0): no t statistic");
  TTest r;
  r.df = df;
  r.conf_level = conf_level;
  r.t = diff / se;
  r.p = t_two_sided_p(r.t, df);
  const double q = boost::math::quantile(boost::math::students_t(df), 0.5 + conf_level / 2);
  r.mean_diff = diff * scale;
  r.se = se * scale;
  r.ci_low = (diff - q * se) * scale;
  r.ci_high = (diff + q * se) * scale;
  for (double v : {r.t, r.df, r.p, r.mean_diff, r.se, r.ci_low, r.ci_high})
    if (!std::isfinite(v)) throw std::domain_error("the interval exceeds the range of double precision");
  return r;
}

}  // namespace

double t_two_sided_p(double t, double df) {
  if (std::isnan(t)) return std::numeric_limits<double>::quiet_NaN();
  if (std::isinf(t)) return 0.0;
  return 2 * boost::math::cdf(boost::math::complement(boost::math::students_t(df), std::abs(t)));
}

TTest paired_t_test(const std::vector<double>& x, const std::vector<double>& y, double conf_level) {
  if (x.size() != y.size() || x.size() < 2) throw std::invalid_argument("paired t-test needs n >= 2 pairs");
  const double s = scale_of(x, y);
  std::vector<double> d(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) d[i] = x[i] / s - y[i] / s;  // scaled first: no overflow
  const Moments m = moments(d, 1.0);
  if (!(m.var > 0)) throw std::domain_error("the differences are all equal (standard deviation 0): no t statistic");
  return finish(m.mean, std::sqrt(m.var / m.n), m.n - 1, conf_level, s);
}

TTest welch_t_test(const std::vector<double>& x, const std::vector<double>& y, double conf_level) {
  if (x.size() < 2 || y.size() < 2) throw std::invalid_argument("Welch t-test needs two values per group");
  const double s = scale_of(x, y);
  const Moments a = moments(x, s), b = moments(y, s);
  const double vx = a.var / a.n, vy = b.var / b.n;
  const double se2 = vx + vy;
  if (!(se2 > 0)) throw std::domain_error("both groups are constant (standard deviation 0): no t statistic");
  const double df = se2 * se2 / (vx * vx / (a.n - 1) + vy * vy / (b.n - 1));
  return finish(a.mean - b.mean, std::sqrt(se2), df, conf_level, s);
}

TTest student_t_test(const std::vector<double>& x, const std::vector<double>& y, double conf_level) {
  if (x.size() < 2 || y.size() < 2) throw std::invalid_argument("Student t-test needs two values per group");
  const double s = scale_of(x, y);
  const Moments a = moments(x, s), b = moments(y, s);
  const double df = a.n + b.n - 2;
  const double pooled = ((a.n - 1) * a.var + (b.n - 1) * b.var) / df;
  if (!(pooled > 0)) throw std::domain_error("both groups are constant (standard deviation 0): no t statistic");
  return finish(a.mean - b.mean, std::sqrt(pooled * (1 / a.n + 1 / b.n)), df, conf_level, s);
}

}  // namespace ms

namespace ms {

namespace {

// Paired: the mean of each subject's observations per level.
void average_per_subject(const TidyCsv& table, const TTestColumns& columns, std::size_t col_s,
                         const std::vector<std::size_t>& row_level, TTestSamples& out) {
  std::vector<std::string> subjects;
  std::map<std::string, std::size_t> subject_index;
  std::vector<std::array<double, 2>> sums;
  std::vector<std::array<int, 2>> counts;
  std::vector<std::size_t> subject_row;
  const std::size_t col_dv = table.column(columns.dv);
  for (std::size_t r = 0; r < table.rows(); ++r) {
    auto [it, added] = subject_index.try_emplace(table.cell(r, col_s), subjects.size());
    if (added) {
      subjects.push_back(table.cell(r, col_s));
      sums.push_back({0, 0});
      counts.push_back({0, 0});
      subject_row.push_back(r);
    }
    sums[it->second][row_level[r]] += table.number(r, col_dv);
    counts[it->second][row_level[r]] += 1;
  }
  for (std::size_t s = 0; s < subjects.size(); ++s) {
    for (std::size_t k = 0; k < 2; ++k) {
      if (counts[s][k] == 0)
        throw InputError(table.where(subject_row[s], col_s), "subject '" + subjects[s] + "' has no observation for " +
                                                                 columns.group + "=" + out.levels[k]);
      out.averaged |= counts[s][k] > 1;
      (k == 0 ? out.first : out.second).push_back(sums[s][k] / counts[s][k]);
    }
  }
  if (subjects.size() < 2) throw InputError(table.where(0, col_s), "a paired t-test needs at least two subjects");
}

}  // namespace

TTestSamples t_test_samples_from_table(const TidyCsv& table, const TTestColumns& columns) {
  const std::size_t col_dv = table.column(columns.dv), col_g = table.column(columns.group);
  const std::size_t col_s = columns.paired ? table.column(columns.subject) : 0;
  if (table.rows() == 0) throw InputError(SourceLocation{table.file(), 0, 0}, "no data rows");
  TTestSamples out;
  std::vector<std::size_t> row_level;
  for (std::size_t r = 0; r < table.rows(); ++r) {
    const double v = table.number(r, col_dv);
    const std::string& g = table.cell(r, col_g);
    std::size_t k = 0;
    while (k < out.levels.size() && out.levels[k] != g) ++k;
    if (k == out.levels.size()) {
      if (out.levels.size() == 2)
        throw InputError(table.where(r, col_g), "column '" + columns.group + "': a third level '" + g +
                                                    "' (a t-test compares exactly two)");
      out.levels.push_back(g);
    }
    row_level.push_back(k);
    if (!columns.paired) (k == 0 ? out.first : out.second).push_back(v);
  }
  if (out.levels.size() < 2)
    throw InputError(table.where(0, col_g), "column '" + columns.group + "' has a single level; need two");
  if (columns.paired) {
    average_per_subject(table, columns, col_s, row_level, out);
  } else {
    for (std::size_t k = 0; k < 2; ++k)
      if ((k == 0 ? out.first : out.second).size() < 2)
        throw InputError(table.where(0, col_g), "level '" + out.levels[k] + "' has fewer than two observations");
  }
  return out;
}

}  // namespace ms
