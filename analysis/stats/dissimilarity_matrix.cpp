#include "analysis/stats/dissimilarity_matrix.hpp"

#include <cmath>
#include <map>

namespace ms {

DissimilarityMatrix dissimilarity_from_square(const TidyCsv& t) {
  const std::size_t n = t.header().size() - 1;
  if (n < 3 || t.rows() != n)
    throw InputError(SourceLocation{t.file(), 1, 1}, "expected a square matrix: a label column and one column per row (" +
                                                         std::to_string(t.rows()) + " rows, " + std::to_string(n) +
                                                         " value columns); need at least 3 stimuli");
  DissimilarityMatrix m;
  m.values.resize(Eigen::Index(n), Eigen::Index(n));
  for (std::size_t i = 0; i < n; ++i) {
    if (t.cell(i, 0) != t.header()[i + 1])
      throw InputError(t.where(i, 0), "row label '" + t.cell(i, 0) + "' differs from column " + std::to_string(i + 2) +
                                          " '" + t.header()[i + 1] + "' (rows and columns must list the same stimuli)");
    m.labels.push_back(t.cell(i, 0));
    for (std::size_t j = 0; j < n; ++j) {
      const double v = t.number(i, j + 1);
      if (v < 0) throw InputError(t.where(i, j + 1), "dissimilarity must not be negative");
      if (i == j && v != 0) throw InputError(t.where(i, j + 1), "the diagonal must be 0 (a stimulus and itself)");
      m.values(Eigen::Index(i), Eigen::Index(j)) = v;
    }
  }
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < i; ++j) {
      const double a = m.values(Eigen::Index(i), Eigen::Index(j)), b = m.values(Eigen::Index(j), Eigen::Index(i));
      if (std::abs(a - b) > 1e-9 * std::max(std::abs(a), std::abs(b)))
        throw InputError(t.where(i, j + 1), "not symmetric: " + t.cell(i, j + 1) + " here but " + t.cell(j, i + 1) +
                                                " for (" + m.labels[j] + ", " + m.labels[i] + ")");
      m.values(Eigen::Index(i), Eigen::Index(j)) = m.values(Eigen::Index(j), Eigen::Index(i)) = 0.5 * (a + b);
    }
  return m;
}

DissimilarityMatrix dissimilarity_from_pairs(const TidyCsv& t, const std::string& first, const std::string& second,
                                             const std::string& value) {
  const std::size_t c1 = t.column(first), c2 = t.column(second), cv = t.column(value);
  DissimilarityMatrix m;
  std::map<std::string, std::size_t> index;
  auto id = [&](const std::string& s) {
    auto [it, added] = index.try_emplace(s, m.labels.size());
    if (added) m.labels.push_back(s);
    return it->second;
  };
  std::map<std::pair<std::size_t, std::size_t>, std::pair<double, int>> acc;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    const double v = t.number(r, cv);
    if (v < 0) throw InputError(t.where(r, cv), "dissimilarity must not be negative");
    std::size_t a = id(t.cell(r, c1)), b = id(t.cell(r, c2));
    if (a == b) continue;  // a stimulus against itself carries no information
    if (a > b) std::swap(a, b);
    auto& cell = acc[{a, b}];
    cell.first += v;
    cell.second += 1;
  }
  const std::size_t n = m.labels.size();
  if (n < 3) throw InputError(SourceLocation{t.file(), 1, 1}, "need pairs over at least 3 stimuli");
  m.values = Eigen::MatrixXd::Zero(Eigen::Index(n), Eigen::Index(n));
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b) {
      const auto it = acc.find({a, b});
      if (it == acc.end())
        throw InputError(SourceLocation{t.file(), 1, 1}, "the pair (" + m.labels[a] + ", " + m.labels[b] +
                                                             ") has no rating; every pair is needed");
      m.averaged_pairs += it->second.second > 1;
      m.values(Eigen::Index(a), Eigen::Index(b)) = m.values(Eigen::Index(b), Eigen::Index(a)) =
          it->second.first / it->second.second;
    }
  return m;
}

}  // namespace ms
