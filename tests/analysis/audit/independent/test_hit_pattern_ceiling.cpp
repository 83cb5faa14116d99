// How often could the audit's hit_position detector tell the independent generator's hit points from
// scatter if it had the true amplitudes? The detector predicts half of a held-out strike's modes from
// the other half (a gain alone, a shared pattern of rank 1-3, or a path through the other strikes'
// patterns) and names hit points when the best of these beats a gain alone by 0.3 dB and beats the same
// on 39 shufflings of each strike's modes. Here that test runs on what the generator rendered: each
// mode's amplitude relative to the strike's gain and to the mode at the reference point (so |shape| at
// the hit point times the jitter), read within +-13 dB as the audit reads its residuals, with no
// extraction, and no room, contact or burst (they are not in these amplitudes). So its figures are a
// ceiling for the audit on these cases. The predictor family is re-implemented here in its essentials
// (four splits into halves as the audit's; least squares where the audit places a strike on its path by
// median and Huber loss; its tilt removal on request, not its contact removal), so the figures say what
// the patterns allow.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "../audit_cases.hpp"
#include "independent_generator.hpp"

namespace ms::test {
namespace {

constexpr double kMaxResidualLn = 1.5;  // the audit's +-13 dB
constexpr double kMinImprovementDb = 0.3;  // the audit's bar
constexpr int kShuffles = 39;
constexpr int kMaxRank = 3;

// Natural-log amplitudes, strikes x modes, with strike gains and mode levels removed.
Eigen::MatrixXd double_centred(Eigen::MatrixXd m) {
  for (int pass = 0; pass < 3; ++pass) {
    m = m.colwise() - m.rowwise().mean();
    m = m.rowwise() - m.colwise().mean();
  }
  return m;
}

// The audit's four splits of a strike's modes: alternate modes, alternate pairs, alternate pairs
// shifted, a fixed scramble.
bool first_half(Eigen::Index n, int split) {
  if (split == 0) return n % 2 == 0;
  if (split == 1) return (n / 2) % 2 == 0;
  if (split == 2) return ((n + 1) / 2) % 2 == 0;
  return ((n * 2654435761u) >> 7) % 2 == 0;
}

// Candidate rows for a held-out strike from the others: rank r (the others' top r right singular
// vectors as columns; r = 0 is a gain alone), or the path (each other strike, and 1/4, 1/2, 3/4 of
// the way between each two).
struct Predictor {
  int rank = 0;
  bool path = false;
};

// Mean squared error, over held-out strikes and both halves of their modes, of predicting one half
// from the other (a gain and the predictor's coefficients fitted on the first half).
double held_out_half_mse(const Eigen::MatrixXd& ln, const Predictor& p) {
  const Eigen::Index strikes = ln.rows(), modes = ln.cols();
  double sse = 0.0;
  std::size_t count = 0;
  for (Eigen::Index h = 0; h < strikes; ++h) {
    std::vector<Eigen::Index> others;
    for (Eigen::Index s = 0; s < strikes; ++s)
      if (s != h) others.push_back(s);
    const Eigen::MatrixXd rest = ln(others, Eigen::all);
    const Eigen::RowVectorXd level = rest.colwise().mean();
    const Eigen::VectorXd y = (ln.row(h) - level).transpose();
    Eigen::MatrixXd basis;  // modes x columns
    if (p.path) {
      std::vector<Eigen::VectorXd> points;
      for (Eigen::Index a = 0; a < rest.rows(); ++a) points.push_back((rest.row(a) - level).transpose());
      for (Eigen::Index a = 0; a < rest.rows(); ++a)
        for (Eigen::Index b = a + 1; b < rest.rows(); ++b)
          for (double t : {0.25, 0.5, 0.75}) points.push_back(((1 - t) * rest.row(a) + t * rest.row(b) - level).transpose());
      basis.resize(modes, Eigen::Index(points.size()));
      for (std::size_t i = 0; i < points.size(); ++i) basis.col(Eigen::Index(i)) = points[i];
    } else if (p.rank > 0) {
      const Eigen::JacobiSVD<Eigen::MatrixXd> svd(double_centred(rest), Eigen::ComputeThinV);
      basis = svd.matrixV().leftCols(p.rank);
    }
    for (int half = 0; half < 8; ++half) {  // four splits, each half predicting the other
      std::vector<Eigen::Index> fit, test;
      for (Eigen::Index n = 0; n < modes; ++n) (first_half(n, half / 2) == (half % 2 == 0) ? fit : test).push_back(n);
      const auto mean_over = [&](const Eigen::VectorXd& v) {
        double s = 0.0;
        for (Eigen::Index n : fit) s += v(n);
        return s / double(fit.size());
      };
      Eigen::VectorXd predicted = Eigen::VectorXd::Constant(modes, mean_over(y));
      if (p.path) {  // the path point nearest on the first half, with its own gain
        double best = INFINITY;
        for (Eigen::Index c = 0; c < basis.cols(); ++c) {
          const Eigen::VectorXd point = basis.col(c);
          const double gain = mean_over(y - point);
          double e = 0.0;
          for (Eigen::Index n : fit) e += std::pow(y(n) - point(n) - gain, 2);
          if (e < best) {
            best = e;
            predicted = point.array() + gain;
          }
        }
      } else if (p.rank > 0) {
        Eigen::MatrixXd x(Eigen::Index(fit.size()), 1 + p.rank);
        Eigen::VectorXd yf(Eigen::Index(fit.size()));
        for (std::size_t i = 0; i < fit.size(); ++i) {
          x(Eigen::Index(i), 0) = 1.0;
          x.row(Eigen::Index(i)).tail(p.rank) = basis.row(fit[i]);
          yf(Eigen::Index(i)) = y(fit[i]);
        }
        const Eigen::VectorXd b = x.colPivHouseholderQr().solve(yf);
        predicted = (basis * b.tail(p.rank)).array() + b(0);
      }
      for (Eigen::Index n : test) sse += std::pow(y(n) - predicted(n), 2);
      count += test.size();
    }
  }
  return count ? sse / double(count) : 0.0;
}

// The best predictor's held-out-half RMS improvement over a gain alone, in dB.
double best_improvement_db(const Eigen::MatrixXd& ln) {
  const double gain_only = std::sqrt(held_out_half_mse(ln, {}));
  double best = gain_only;
  const int most = std::min<int>(kMaxRank, int(std::min(ln.rows() - 2, ln.cols() / 2 - 2)));
  for (int r = 1; r <= most; ++r) best = std::min(best, std::sqrt(held_out_half_mse(ln, {r, false})));
  if (ln.rows() >= 4) best = std::min(best, std::sqrt(held_out_half_mse(ln, {0, true})));
  return 20.0 / std::log(10.0) * (gain_only - best);
}

struct Verdict {
  std::size_t strikes = 0;
  double jitter_db = 0.0, improvement_db = 0.0, top_shuffled_db = 0.0;
  bool told() const { return improvement_db >= kMinImprovementDb && improvement_db > top_shuffled_db; }
};

// The case of `seed` hiding `effects` at `strengths` (none: jitter alone), judged on its true amplitudes.
Verdict judge_case(std::uint64_t seed, const std::vector<std::string>& effects, const std::vector<double>& strengths,
                   std::size_t max_modes) {
  const indep::IndependentCase c = indep::generate_independent_case(seed, effects, strengths);
  // The strongest max_modes modes at the reference point (the audit reads the modes it tracked).
  const auto reference = [&](std::size_t n) {
    const indep::ObjectMode& m = c.object[n];
    return m.weight * std::abs(std::sin(m.wavenumber * c.reference_x + m.shape_phase_rad));
  };
  std::vector<std::size_t> kept(c.object.size());
  std::iota(kept.begin(), kept.end(), std::size_t(0));
  std::stable_sort(kept.begin(), kept.end(), [&](std::size_t a, std::size_t b) { return reference(a) > reference(b); });
  kept.resize(std::min(kept.size(), max_modes));
  std::sort(kept.begin(), kept.end());  // by frequency, as the audit's columns
  const Eigen::Index strikes = Eigen::Index(c.strikes.size()), modes = Eigen::Index(kept.size());
  Eigen::MatrixXd ln(strikes, modes);  // ln(amplitude / (strike gain x the mode at the reference point))
  for (Eigen::Index s = 0; s < strikes; ++s)
    for (Eigen::Index j = 0; j < modes; ++j) {
      const std::size_t n = kept[std::size_t(j)];
      const double amp = std::abs(c.strikes[std::size_t(s)].modes[n].amp);  // a shape's sign is a phase
      const double gain = std::pow(10.0, c.strikes[std::size_t(s)].gain_db / 20.0);
      ln(s, j) = std::log(amp / (gain * reference(n)));
    }
  // The rendering's overall scale out (the audit's model fits the modes' levels), then read as the audit
  // reads its residuals.
  ln = ln.array() - ln.mean();
  ln = ln.cwiseMax(-kMaxResidualLn).cwiseMin(kMaxResidualLn);
  // Each row's smooth tilt (1, log f, log^2 f) out, as the audit does.
  static const bool tilt = std::getenv("HIT_CEILING_TILT") != nullptr;
  Eigen::MatrixXd projector = Eigen::MatrixXd::Zero(modes, modes);
  if (tilt) {
    Eigen::MatrixXd basis(modes, 3);
    for (Eigen::Index j = 0; j < modes; ++j) {
      const double x = std::log(c.object[kept[std::size_t(j)]].freq_hz / 1000.0);
      basis.row(j) << 1.0, x, x * x;
    }
    projector = basis * basis.completeOrthogonalDecomposition().pseudoInverse();
  }
  const auto taken_out = [&](const Eigen::MatrixXd& m) -> Eigen::MatrixXd {
    return tilt ? Eigen::MatrixXd(m - m * projector.transpose()) : m;
  };
  Verdict v;
  v.strikes = c.strikes.size();
  v.jitter_db = c.jitter_db;
  v.improvement_db = best_improvement_db(taken_out(ln));
  std::mt19937_64 rng(seed);
  v.top_shuffled_db = -INFINITY;
  for (int t = 0; t < kShuffles; ++t) {
    Eigen::MatrixXd shuffled = ln;
    for (Eigen::Index s = 0; s < strikes; ++s) {
      std::vector<Eigen::Index> order(static_cast<std::size_t>(modes));
      std::iota(order.begin(), order.end(), 0);
      std::shuffle(order.begin(), order.end(), rng);
      for (Eigen::Index n = 0; n < modes; ++n) shuffled(s, n) = ln(s, order[std::size_t(n)]);
    }
    v.top_shuffled_db = std::max(v.top_shuffled_db, best_improvement_db(taken_out(shuffled)));
  }
  return v;
}

std::size_t env_count(const char* name, std::size_t fallback) {
  const char* v = std::getenv(name);
  return v ? std::size_t(std::strtoull(v, nullptr, 10)) : fallback;
}

void print_case(std::uint64_t seed, const Verdict& v) {
  std::printf("case %llu: %zu strikes, jitter %.2f dB, pattern %.2f dB better than a gain alone, shuffled at most %.2f: %s\n",
              (unsigned long long)seed, v.strikes, v.jitter_db, v.improvement_db, v.top_shuffled_db,
              v.told() ? "told" : "not told");
}

// By strikes: 6, 7-8, 9-10 (a held-out strike learns its pattern from the others).
struct ByStrikes {
  int told[3] = {0, 0, 0}, seen[3] = {0, 0, 0};
  void add(const Verdict& v) {
    const std::size_t b = v.strikes <= 6 ? 0 : v.strikes <= 8 ? 1 : 2;
    ++seen[b];
    told[b] += v.told();
  }
  void print() const {
    std::printf("strikes 6: %d/%d | 7-8: %d/%d | 9-10: %d/%d\n", told[0], seen[0], told[1], seen[1], told[2], seen[2]);
  }
};

// Seeds 90000 on (the audit never runs on them here, so no held-out seed is spent). Prints the share
// told from scatter per strength, per jitter and per number of strikes; HIT_CEILING_CASES per strength
// (default 60), HIT_CEILING_MAX_MODES the strongest modes kept (default all of the object's 15-40),
// HIT_CEILING_TILT each strike's smooth tilt taken out as the audit does, HIT_CEILING_PRINT every case.
TEST(AuditIndependent, DISABLED_HitPatternCeiling) {
  const std::size_t per_strength = env_count("HIT_CEILING_CASES", 60);
  const std::size_t max_modes = env_count("HIT_CEILING_MAX_MODES", 1000);
  const std::vector<double> strengths{0.1, 0.4, 0.7, 1.0};
  const std::vector<double> jitter_edges{1.0, 1.67, 2.33, 3.01};
  std::vector<std::vector<int>> told(strengths.size(), std::vector<int>(3, 0)), seen = told;
  ByStrikes by_strikes;
  std::uint64_t seed = 90000;
  int all_told = 0, all = 0;
  for (std::size_t i = 0; i < strengths.size(); ++i)
    for (std::size_t k = 0; k < per_strength; ++k, ++seed) {
      const Verdict v = judge_case(seed, {"hit_position"}, {strengths[i]}, max_modes);
      if (std::getenv("HIT_CEILING_PRINT")) print_case(seed, v);
      const std::size_t j = v.jitter_db < jitter_edges[1] ? 0 : v.jitter_db < jitter_edges[2] ? 1 : 2;
      ++seen[i][j];
      told[i][j] += v.told();
      all_told += v.told();
      ++all;
      by_strikes.add(v);
    }
  std::printf("hit points told from scatter (true amplitudes, the detector's test):\n");
  std::printf("strength | jitter 1-1.67 dB | 1.67-2.33 dB | 2.33-3 dB\n");
  for (std::size_t i = 0; i < strengths.size(); ++i)
    std::printf("%.1f | %d/%d | %d/%d | %d/%d\n", strengths[i], told[i][0], seen[i][0], told[i][1], seen[i][1],
                told[i][2], seen[i][2]);
  by_strikes.print();
  std::printf("all: %d/%d (%.0f %%)\n", all_told, all, 100.0 * all_told / std::max(all, 1));
  // The instrument works: with the least jitter nearly every hit point is told from scatter.
  int low_told = 0, low_seen = 0;
  for (std::size_t i = 0; i < strengths.size(); ++i) {
    low_told += told[i][0];
    low_seen += seen[i][0];
  }
  EXPECT_GE(double(low_told), 0.85 * double(low_seen));
}

// The same seeds with no hit point hidden (jitter alone): how often the test tells a pattern that is
// not there, and how large the best predictor's gain over a gain alone gets (what the bar must clear).
TEST(AuditIndependent, DISABLED_HitPatternCeilingWithoutHitPoints) {
  const std::size_t cases = 4 * env_count("HIT_CEILING_CASES", 60), max_modes = env_count("HIT_CEILING_MAX_MODES", 1000);
  int told = 0;
  double largest_db = -INFINITY;
  for (std::uint64_t seed = 90000; seed < 90000 + cases; ++seed) {
    const Verdict v = judge_case(seed, {}, {}, max_modes);
    if (std::getenv("HIT_CEILING_PRINT")) print_case(seed, v);
    told += v.told();
    largest_db = std::max(largest_db, v.improvement_db);
  }
  std::printf("without hit points: %d/%zu told; the largest gain over a gain alone %.2f dB (bar %.2f)\n", told, cases,
              largest_db, kMinImprovementDb);
  EXPECT_LE(double(told), double(cases) / (kShuffles + 1));  // no more than the shuffles' p allows
}

// The ceiling of one held-out run (HIT_CEILING_HELDOUT=first seed, as INDEPENDENT_HELDOUT_FIRST): each of
// its cases that hides a hit point, with the other effect it hides beside it, judged on its true
// amplitudes. Nothing is audited, so no seed is spent; it says how many of the run's hit points any
// detector of this kind could name.
TEST(AuditIndependent, DISABLED_HitPatternCeilingOfHeldOutRun) {
  const char* first = std::getenv("HIT_CEILING_HELDOUT");
  ASSERT_NE(first, nullptr) << "set HIT_CEILING_HELDOUT=first seed of the run";
  const std::uint64_t f = std::strtoull(first, nullptr, 10);
  const std::size_t max_modes = env_count("HIT_CEILING_MAX_MODES", 1000);
  ByStrikes by_strikes;
  int told = 0, seen = 0;
  for (std::uint64_t half = 0; half < 2; ++half)  // the run's two halves of 110 cases, planned as the audit's
    for (std::size_t i = 0; i < 110; ++i) {
      const std::uint64_t seed = f + 110 * half + i;
      const CasePlan plan = plan_case(seed, i, false, indep::independent_effects());
      if (std::ranges::find(plan.effects, std::string("hit_position")) == plan.effects.end()) continue;
      const Verdict v = judge_case(seed, plan.effects, plan.strengths, max_modes);
      print_case(seed, v);
      by_strikes.add(v);
      told += v.told();
      ++seen;
    }
  by_strikes.print();
  std::printf("all: %d/%d\n", told, seen);
  EXPECT_GT(seen, 0);
}

}  // namespace
}  // namespace ms::test
