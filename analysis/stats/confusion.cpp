#include "analysis/stats/confusion.hpp"

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <unordered_map>

namespace ms {

Confusion confusion_from_pairs(const std::vector<std::string>& labels, const std::vector<std::string>& truth,
                               const std::vector<std::string>& response) {
  if (truth.size() != response.size()) throw std::invalid_argument("truth and response differ in length");
  std::unordered_map<std::string, Eigen::Index> index;
  for (std::size_t i = 0; i < labels.size(); ++i) index.emplace(labels[i], Eigen::Index(i));
  Confusion c{labels, Eigen::MatrixXd::Zero(Eigen::Index(labels.size()), Eigen::Index(labels.size()))};
  for (std::size_t k = 0; k < truth.size(); ++k) c.counts(index.at(truth[k]), index.at(response[k])) += 1;
  return c;
}

Eigen::MatrixXd row_percent(const Eigen::MatrixXd& counts) {
  Eigen::MatrixXd p = counts;
  for (Eigen::Index i = 0; i < p.rows(); ++i) {
    const double n = counts.row(i).sum();
    if (n > 0) p.row(i) *= 100.0 / n;
  }
  return p;
}

double accuracy(const Eigen::MatrixXd& counts) { return counts.diagonal().sum() / counts.sum(); }

std::vector<double> recall(const Eigen::MatrixXd& counts) {
  std::vector<double> r;
  for (Eigen::Index i = 0; i < counts.rows(); ++i) {
    const double n = counts.row(i).sum();
    r.push_back(n > 0 ? counts(i, i) / n : std::numeric_limits<double>::quiet_NaN());
  }
  return r;
}

double cohen_kappa(const Eigen::MatrixXd& counts) {
  const double n = counts.sum();
  const double po = counts.diagonal().sum() / n;
  const double pe = (counts.rowwise().sum().array() * counts.colwise().sum().transpose().array()).sum() / (n * n);
  return (po - pe) / (1 - pe);
}

ChiSquareTest chi2_independence(const Eigen::MatrixXd& counts) {
  std::vector<Eigen::Index> rows, cols;
  for (Eigen::Index i = 0; i < counts.rows(); ++i)
    if (counts.row(i).sum() > 0) rows.push_back(i);
  for (Eigen::Index j = 0; j < counts.cols(); ++j)
    if (counts.col(j).sum() > 0) cols.push_back(j);
  ChiSquareTest t;
  if (rows.size() < 2 || cols.size() < 2) {
    t.chi2 = 0;
    t.df = 0;
    t.p = std::numeric_limits<double>::quiet_NaN();
    return t;
  }
  const Eigen::MatrixXd o = counts(rows, cols);
  const Eigen::VectorXd rs = o.rowwise().sum();
  const Eigen::RowVectorXd cs = o.colwise().sum();
  const double n = o.sum();
  t.df = double(rows.size() - 1) * double(cols.size() - 1);
  t.yates = t.df == 1;
  for (Eigen::Index i = 0; i < o.rows(); ++i)
    for (Eigen::Index j = 0; j < o.cols(); ++j) {
      const double e = rs(i) * cs(j) / n;
      double dev = std::abs(o(i, j) - e);
      if (t.yates) dev = std::max(0.0, dev - 0.5);  // scipy: shrink |O - E| by 0.5, not past 0
      t.chi2 += dev * dev / e;
    }
  t.p = t.chi2 > 0 ? boost::math::cdf(boost::math::complement(boost::math::chi_squared(t.df), t.chi2)) : 1.0;
  return t;
}

double frobenius_distance(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return (a - b).norm(); }

Interval wilson_interval(double x, double n, double conf_level) {
  const double z = boost::math::quantile(boost::math::normal(), 0.5 + conf_level / 2);
  const double denom = n + z * z;
  const double centre = (x + z * z / 2) / denom;
  const double half = z * std::sqrt(x * (n - x) / n + z * z / 4) / denom;
  return {std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

Interval newcombe_difference(double x1, double n1, double x2, double n2, double conf_level) {
  const Interval a = wilson_interval(x1, n1, conf_level), b = wilson_interval(x2, n2, conf_level);
  const double p1 = x1 / n1, p2 = x2 / n2, d = p1 - p2;
  return {d - std::sqrt((p1 - a.low) * (p1 - a.low) + (b.high - p2) * (b.high - p2)),
          d + std::sqrt((a.high - p1) * (a.high - p1) + (p2 - b.low) * (p2 - b.low))};
}

Interval wald_difference(double x1, double n1, double x2, double n2, bool continuity_correction, double conf_level) {
  const double z = boost::math::quantile(boost::math::normal(), 0.5 + conf_level / 2);
  const double p1 = x1 / n1, p2 = x2 / n2, d = p1 - p2, inv_n = 1 / n1 + 1 / n2;
  const double yates = continuity_correction ? std::min(0.5, std::abs(d) / inv_n) : 0.0;
  const double width = z * std::sqrt(p1 * (1 - p1) / n1 + p2 * (1 - p2) / n2) + yates * inv_n;
  return {std::max(d - width, -1.0), std::min(d + width, 1.0)};
}

}  // namespace ms

namespace ms {

ConfusionResponses confusion_responses_from_table(const TidyCsv& table, const std::string& truth_column,
                                                  const std::string& response_column,
                                                  const std::vector<std::string>& labels) {
  const std::size_t ct = table.column(truth_column), cr = table.column(response_column);
  if (table.rows() == 0) throw InputError(SourceLocation{table.file(), 0, 0}, "no data rows");
  ConfusionResponses out;
  for (std::size_t i = 0; i < table.rows(); ++i)
    for (std::size_t c : {ct, cr}) {
      const std::string& v = table.cell(i, c);
      if (v.empty()) throw InputError(table.where(i, c), "column '" + table.header()[c] + "': empty label");
      if (!labels.empty() && std::find(labels.begin(), labels.end(), v) == labels.end())
        throw InputError(table.where(i, c), "column '" + table.header()[c] + "': label '" + v + "' is not in --labels");
      (c == ct ? out.truth : out.response).push_back(v);
    }
  return out;
}

}  // namespace ms
