// Textbook reference for within-subject ANOVA: sums of squares from marginal means, recomputed by
// loops over the long-format data for every effect (no matrices). Used to cross-check rm_anova and
// as the naive baseline in bench_rm_anova. Balanced designs, one observation per subject and cell.
#pragma once
#include <bit>
#include <cstddef>
#include <vector>

namespace ms::test {

struct LongRow {
  int subject;
  std::vector<int> level;  // one level index per within factor
  double y;
};

struct NaiveEffect {
  unsigned mask;  // within factors in the effect
  double ss, ss_error, df1, df2, F;
};

// Effect term of subset E evaluated at a row: alpha_E = sum over S subset of E of (-1)^{|E|-|S|} m_S,
// m_S = mean over the rows sharing the row's levels of the factors in S (grand mean for S empty).
// Factor index k == levels.size() stands for the subject. SS_E = sum over rows of alpha_E^2.
inline double naive_ss(const std::vector<LongRow>& rows, const std::vector<int>& levels, int n_subjects,
                       unsigned mask) {
  const std::size_t k = levels.size();
  std::vector<int> count_of(k + 1);
  for (std::size_t f = 0; f < k; ++f) count_of[f] = levels[f];
  count_of[k] = n_subjects;
  auto level_of = [&](const LongRow& r, std::size_t f) { return f == k ? r.subject : r.level[f]; };
  // Marginal means for every subset of `mask`, each by one pass over the rows.
  std::vector<std::vector<double>> means(std::size_t(1) << (k + 1));
  for (unsigned s = mask;; s = (s - 1) & mask) {
    std::size_t cells = 1;
    for (std::size_t f = 0; f <= k; ++f)
      if (s & (1u << f)) cells *= std::size_t(count_of[f]);
    std::vector<double> sum(cells, 0.0), cnt(cells, 0.0);
    for (const auto& r : rows) {
      std::size_t idx = 0;
      for (std::size_t f = 0; f <= k; ++f)
        if (s & (1u << f)) idx = idx * std::size_t(count_of[f]) + std::size_t(level_of(r, f));
      sum[idx] += r.y;
      cnt[idx] += 1;
    }
    for (std::size_t c = 0; c < cells; ++c) sum[c] /= cnt[c];
    means[s] = std::move(sum);
    if (s == 0) break;
  }
  double ss = 0;
  for (const auto& r : rows) {
    double alpha = 0;
    for (unsigned s = mask;; s = (s - 1) & mask) {
      std::size_t idx = 0;
      for (std::size_t f = 0; f <= k; ++f)
        if (s & (1u << f)) idx = idx * std::size_t(count_of[f]) + std::size_t(level_of(r, f));
      const int sign = (std::popcount(mask) - std::popcount(s)) % 2 ? -1 : 1;
      alpha += sign * means[s][idx];
      if (s == 0) break;
    }
    ss += alpha * alpha;
  }
  return ss;
}

// All within effects in R's term order (by degree, then mask); error term = effect x subject.
inline std::vector<NaiveEffect> naive_within_anova(const std::vector<LongRow>& rows, const std::vector<int>& levels,
                                                   int n_subjects) {
  const std::size_t k = levels.size();
  std::vector<unsigned> masks;
  for (int degree = 1; degree <= int(k); ++degree)
    for (unsigned m = 1; m < (1u << k); ++m)
      if (std::popcount(m) == degree) masks.push_back(m);
  std::vector<NaiveEffect> out;
  for (unsigned m : masks) {
    NaiveEffect e{};
    e.mask = m;
    e.df1 = 1;
    for (std::size_t f = 0; f < k; ++f)
      if (m & (1u << f)) e.df1 *= levels[f] - 1;
    e.df2 = e.df1 * (n_subjects - 1);
    e.ss = naive_ss(rows, levels, n_subjects, m);
    e.ss_error = naive_ss(rows, levels, n_subjects, m | (1u << k));
    e.F = (e.ss / e.df1) / (e.ss_error / e.df2);
    out.push_back(e);
  }
  return out;
}

}  // namespace ms::test
