#include "analysis/stats/posthoc.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "analysis/stats/t_test.hpp"

namespace ms {

const char* p_adjust_name(PAdjust method) {
  switch (method) {
    case PAdjust::none: return "none";
    case PAdjust::holm: return "holm";
    case PAdjust::bonferroni: return "bonferroni";
  }
  return "none";
}

PAdjust p_adjust_from_name(const std::string& name) {
  for (PAdjust m : {PAdjust::none, PAdjust::holm, PAdjust::bonferroni})
    if (name == p_adjust_name(m)) return m;
  throw std::invalid_argument("unknown p adjustment '" + name + "' (use holm, bonferroni or none)");
}

std::vector<double> p_adjust(const std::vector<double>& p, PAdjust method) {
  const double m = double(p.size());
  std::vector<double> out(p);
  if (method == PAdjust::bonferroni) {
    for (double& v : out) v = std::min(1.0, v * m);
  } else if (method == PAdjust::holm) {
    std::vector<std::size_t> order(p.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p[a] < p[b]; });
    double running = 0;
    for (std::size_t i = 0; i < order.size(); ++i) {
      running = std::max(running, std::min(1.0, (m - double(i)) * p[order[i]]));
      out[order[i]] = running;
    }
  }
  return out;
}

namespace {

// Per subject, the mean over all within cells whose level of factor `f` is `level`.
std::vector<double> marginal_means(const RmData& data, std::size_t f, std::size_t level) {
  std::size_t stride = 1;
  for (std::size_t k = f + 1; k < data.within.size(); ++k) stride *= data.within[k].levels.size();
  const std::size_t n_levels = data.within[f].levels.size();
  std::vector<double> means(data.subjects.size(), 0.0);
  for (std::size_t s = 0; s < data.subjects.size(); ++s) {
    double sum = 0;
    std::size_t count = 0;
    for (std::size_t cell = 0; cell < data.cells(); ++cell)
      if ((cell / stride) % n_levels == level) {
        sum += data.cell_mean(Eigen::Index(s), Eigen::Index(cell));
        ++count;
      }
    means[s] = sum / double(count);
  }
  return means;
}

// Per subject, the mean over every within cell (the subject's score in a between comparison).
std::vector<double> subject_means(const RmData& data) {
  std::vector<double> means(data.subjects.size());
  for (std::size_t s = 0; s < means.size(); ++s) means[s] = data.cell_mean.row(Eigen::Index(s)).mean();
  return means;
}

void within_pairs(const RmData& data, std::size_t f, Posthoc& out) {
  const auto& levels = data.within[f].levels;
  for (std::size_t a = 0; a < levels.size(); ++a)
    for (std::size_t b = a + 1; b < levels.size(); ++b) {
      const TTest t = paired_t_test(marginal_means(data, f, a), marginal_means(data, f, b));
      out.pairs.push_back({levels[a], levels[b], t.mean_diff, t.t, t.df, t.p, t.p});
    }
}

void between_pairs(const RmData& data, std::size_t f, Posthoc& out) {
  const auto& levels = data.between[f].levels;
  const std::vector<double> score = subject_means(data);
  std::vector<double> sum(levels.size(), 0.0), sum_sq(levels.size(), 0.0), n(levels.size(), 0.0);
  for (std::size_t s = 0; s < score.size(); ++s) {
    const auto g = std::size_t(data.between_level(Eigen::Index(s), Eigen::Index(f)));
    sum[g] += score[s];
    n[g] += 1;
  }
  for (std::size_t s = 0; s < score.size(); ++s) {
    const auto g = std::size_t(data.between_level(Eigen::Index(s), Eigen::Index(f)));
    const double dev = score[s] - sum[g] / n[g];
    sum_sq[g] += dev * dev;
  }
  const double df = double(score.size()) - double(levels.size());
  const double pooled_var = std::accumulate(sum_sq.begin(), sum_sq.end(), 0.0) / df;
  if (!(df > 0) || !(pooled_var > 0))
    throw std::domain_error("between-groups comparison of '" + data.between[f].name +
                            "' is undefined: no variation within the groups");
  for (std::size_t a = 0; a < levels.size(); ++a)
    for (std::size_t b = a + 1; b < levels.size(); ++b) {
      const double diff = sum[a] / n[a] - sum[b] / n[b];
      const double t = diff / std::sqrt(pooled_var * (1 / n[a] + 1 / n[b]));
      const double p = t_two_sided_p(t, df);
      out.pairs.push_back({levels[a], levels[b], diff, t, df, p, p});
    }
}

}  // namespace

Posthoc pairwise_t_tests(const RmData& data, const std::string& factor, PAdjust method) {
  Posthoc out;
  out.factor = factor;
  out.method = method;
  bool found = false;
  for (std::size_t f = 0; f < data.within.size() && !found; ++f)
    if (data.within[f].name == factor) {
      within_pairs(data, f, out);
      found = true;
    }
  for (std::size_t f = 0; f < data.between.size() && !found; ++f)
    if (data.between[f].name == factor) {
      out.within = false;
      between_pairs(data, f, out);
      found = true;
    }
  if (!found) throw std::invalid_argument("'" + factor + "' is not a factor of the design");
  std::vector<double> p;
  for (const auto& c : out.pairs) p.push_back(c.p);
  const std::vector<double> adjusted = p_adjust(p, method);
  for (std::size_t i = 0; i < out.pairs.size(); ++i) out.pairs[i].p_adjusted = adjusted[i];
  return out;
}

}  // namespace ms
