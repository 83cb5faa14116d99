// A bending-wave line learnt from a few strikes: where each strike landed, and what a strike the line
// has not seen sounds like, from the modes' log amplitudes alone.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include "analysis/audit/bending_line.hpp"

namespace ms::audit {
namespace {

// Strikes at coordinates u (radians of the lowest mode's shape) on a line whose modes are a free bar's
// (frequencies as (2n + 1)^2, wavenumbers as their square roots), each strike with its own gain, the
// modes with their own levels, and `noise_ln` of per-mode scatter.
struct Line {
  std::vector<double> freq_hz, phase_rad, level_ln;
};

Line a_bar(std::mt19937_64& rng, int modes) {
  std::uniform_real_distribution<double> U(0.0, 1.0);
  Line l;
  for (int n = 0; n < modes; ++n) {
    l.freq_hz.push_back(200.0 * (2 * n + 3) * (2 * n + 3) / 9.0);
    l.phase_rad.push_back(std::numbers::pi * U(rng));
    l.level_ln.push_back(-2.0 * U(rng));
  }
  return l;
}

Eigen::MatrixXd strikes_at(const Line& l, const std::vector<double>& u_rad, double noise_ln, std::mt19937_64& rng) {
  std::normal_distribution<double> N(0.0, 1.0);
  Eigen::MatrixXd ln(Eigen::Index(u_rad.size()), Eigen::Index(l.freq_hz.size()));
  for (std::size_t s = 0; s < u_rad.size(); ++s) {
    const double gain_ln = 0.5 * N(rng);
    for (std::size_t n = 0; n < l.freq_hz.size(); ++n) {
      const double k = std::sqrt(l.freq_hz[n] / l.freq_hz.front());
      ln(Eigen::Index(s), Eigen::Index(n)) =
          gain_ln + l.level_ln[n] + std::log(0.1 + std::abs(std::sin(k * u_rad[s] + l.phase_rad[n]))) + noise_ln * N(rng);
    }
  }
  return ln;
}

// RMS (natural log) of a row against the best of `candidates`' rows, each with its own gain.
double best_rms(const Eigen::RowVectorXd& row, const Eigen::MatrixXd& candidates) {
  double best = 1e9;
  for (Eigen::Index p = 0; p < candidates.rows(); ++p) {
    const Eigen::RowVectorXd d = row - candidates.row(p);
    best = std::min(best, std::sqrt((d.array() - d.mean()).square().mean()));
  }
  return best;
}

TEST(BendingLine, FindsHowFarApartFiveStrikesLandedFromTheirModes) {
  std::mt19937_64 rng(7);
  const Line bar = a_bar(rng, 20);
  const std::vector<double> u = {-0.3, -0.1, 0.0, 0.2, 0.35};
  const BendingLine line = fit_bending_line(strikes_at(bar, u, 0.05, rng), bar.freq_hz);
  ASSERT_EQ(line.strike_at.size(), u.size());
  // Only distances along the line are defined (a shift is absorbed by the phases, and the line may run
  // either way).
  const double sign = line.strike_u[4] > line.strike_u[0] ? 1.0 : -1.0;
  for (std::size_t s = 1; s < u.size(); ++s)
    EXPECT_NEAR(sign * (line.strike_u[s] - line.strike_u[0]), u[s] - u[0], 0.03) << "strike " << s;
}

// The upper modes pass nodes between strikes, so no mean of the others predicts a new strike; a point
// on the line learnt from four strikes does, to within the scatter.
TEST(BendingLine, PredictsAStrikeItHasNotSeen) {
  std::mt19937_64 rng(11);
  const Line bar = a_bar(rng, 20);
  const Eigen::MatrixXd seen = strikes_at(bar, {-0.4, -0.15, 0.1, 0.4}, 0.05, rng);
  const Eigen::RowVectorXd unseen = strikes_at(bar, {0.25}, 0.05, rng).row(0);
  const BendingLine line = fit_bending_line(seen, bar.freq_hz);
  const double on_line = best_rms(unseen, line.shapes());
  const double mean_of_others = best_rms(unseen, seen.colwise().mean());
  EXPECT_LT(on_line, 0.15);
  EXPECT_GT(mean_of_others, 3.0 * on_line);
}

TEST(BendingLine, NoRowsOrNoModesLearnNothingAndFrequenciesMustMatchTheColumns) {
  EXPECT_TRUE(fit_bending_line(Eigen::MatrixXd(0, 3), {100.0, 200.0, 300.0}).strike_at.empty());
  EXPECT_TRUE(fit_bending_line(Eigen::MatrixXd(3, 0), {}).strike_at.empty());
  EXPECT_THROW(fit_bending_line(Eigen::MatrixXd::Zero(3, 3), {100.0, 200.0}), std::invalid_argument);
}

}  // namespace
}  // namespace ms::audit
