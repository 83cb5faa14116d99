#include "analysis/audit/bending_line.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>

namespace ms::audit {

namespace {

constexpr double kNodeFloor = 0.1;  // a node keeps a tenth of an antinode's amplitude (-20 dB)

// ln(floor + |sin(phi)|) from a table over one period of |sin| (pi): the fit evaluates it millions of
// times per audit round.
constexpr int kTable = 1024;
const std::array<double, kTable>& shape_table() {
  static const std::array<double, kTable> table = [] {
    std::array<double, kTable> t{};
    for (int i = 0; i < kTable; ++i) t[std::size_t(i)] = std::log(kNodeFloor + std::sin(std::numbers::pi * (i + 0.5) / kTable));
    return t;
  }();
  return table;
}

double shape_ln(double phi_rad) {
  const long i = long(std::floor(phi_rad * (kTable / std::numbers::pi)));
  return shape_table()[std::size_t(((i % kTable) + kTable) % kTable)];
}

constexpr int kPhasesCoarse = 16;  // theta_n tried first on [0, pi) (|sin| has period pi), then refined
constexpr int kRefinements = 5;    // halvings of the step around the best coarse value
constexpr double kCoarseStepRad = 0.05;  // strikes' coordinates tried first, then refined
constexpr int kIterations = 8;     // alternations of the phases and the strikes' coordinates
// Starting spreads of the strikes' coordinates (radians of the lowest mode), along their first pattern
// in the lower modes (whose shapes bend least between strikes): a hand moving millimetres to
// centimetres on a bar a few decimetres long.
constexpr double kStartSpreadRad[] = {0.1, 0.2, 0.35, 0.5, 0.7, 1.0};
constexpr int kRandomStarts = 6;  // and strikes placed at random, for lines the first pattern misorders
// The fit's stages: the modes of wavenumber up to these multiples of the lowest's, then all; the first
// stage's modes also order the strikes for the starts.
constexpr double kStageRatios[] = {2.5, 4.0, 7.0};
constexpr std::size_t kMinStageModes = 3;

std::size_t nearest_on_grid(double u_rad) {
  const std::vector<double>& grid = line_grid_rad();
  const auto it = std::lower_bound(grid.begin(), grid.end(), u_rad);
  if (it == grid.begin()) return 0;
  if (it == grid.end()) return grid.size() - 1;
  return std::size_t(it - grid.begin()) - (u_rad - *(it - 1) < *it - u_rad ? 1 : 0);
}

// The value of x in [lo, hi) (periodic: the interval wraps) that minimises cost(x): every `step` first,
// then the best of those refined by halving steps (the cost varies smoothly near its minimum).
template <typename Cost>
double coarse_to_fine_min(double lo, double hi, double step, bool periodic, Cost cost) {
  double best = lo, best_cost = std::numeric_limits<double>::infinity();
  for (double x = lo; x < hi; x += step)
    if (const double c = cost(x); c < best_cost) {
      best_cost = c;
      best = x;
    }
  for (int i = 0; i < kRefinements; ++i) {
    step /= 2.0;
    const double centre = best;
    for (double x : {centre - step, centre + step}) {
      if (!periodic && (x < lo || x > hi)) continue;
      if (const double c = cost(x); c < best_cost) {
        best_cost = c;
        best = x;
      }
    }
  }
  return best;
}

// Least-squares fit of the line from one start (its strikes' coordinates); returns its sum of squared
// errors. Alternates: each mode's phase and offset given the strikes, each strike's coordinate and
// gain given the modes. The gains start at each strike's mean.
double fit_from(const Eigen::MatrixXd& ln, BendingLine& line) {
  const std::vector<double>& grid = line_grid_rad();
  const Eigen::Index strikes = ln.rows(), modes = ln.cols();
  std::vector<double> gain(static_cast<std::size_t>(strikes));
  for (Eigen::Index s = 0; s < strikes; ++s) gain[std::size_t(s)] = ln.row(s).mean();
  double sse = std::numeric_limits<double>::infinity();
  for (int it = 0; it < kIterations; ++it) {
    for (Eigen::Index n = 0; n < modes; ++n) {
      const double r = line.ratio[std::size_t(n)];
      double offset = 0.0;
      const auto cost = [&](double theta) {
        double sum = 0.0, sum2 = 0.0;
        for (Eigen::Index s = 0; s < strikes; ++s) {
          const double d = ln(s, n) - gain[std::size_t(s)] - shape_ln(r * line.strike_u[std::size_t(s)] + theta);
          sum += d;
          sum2 += d * d;
        }
        offset = sum / double(strikes);
        return sum2 - sum * sum / double(strikes);
      };
      const double theta = coarse_to_fine_min(0.0, std::numbers::pi, std::numbers::pi / kPhasesCoarse, true, cost);
      cost(theta);  // its offset
      line.phase_rad[std::size_t(n)] = theta;
      line.offset_ln[std::size_t(n)] = offset;
    }
    sse = 0.0;
    for (Eigen::Index s = 0; s < strikes; ++s) {
      double level = 0.0;
      const auto cost = [&](double u) {
        double sum = 0.0, sum2 = 0.0;
        for (Eigen::Index n = 0; n < modes; ++n) {
          const std::size_t m = std::size_t(n);
          const double d = ln(s, n) - line.offset_ln[m] - shape_ln(line.ratio[m] * u + line.phase_rad[m]);
          sum += d;
          sum2 += d * d;
        }
        level = sum / double(modes);
        return sum2 - sum * sum / double(modes);
      };
      const double u = coarse_to_fine_min(grid.front(), grid.back(), kCoarseStepRad, false, cost);
      sse += cost(u);
      line.strike_u[std::size_t(s)] = u;
      gain[std::size_t(s)] = level;
    }
  }
  return sse;
}

// The fit from the strikes' starting coordinates in stages, the lower modes first: their shapes bend
// little between strikes, so they place the strikes roughly without the many false minima of the upper
// modes, each stage adding modes up to a higher wavenumber and refining where the strikes landed.
double fit_in_stages(const Eigen::MatrixXd& ln, BendingLine& line) {
  for (double most : kStageRatios) {
    std::vector<Eigen::Index> cols;
    for (Eigen::Index n = 0; n < ln.cols(); ++n)
      if (line.ratio[std::size_t(n)] <= most) cols.push_back(n);
    if (cols.size() < kMinStageModes || cols.size() == std::size_t(ln.cols())) continue;
    BendingLine stage;
    for (Eigen::Index n : cols) stage.ratio.push_back(line.ratio[std::size_t(n)]);
    stage.phase_rad.assign(cols.size(), 0.0);
    stage.offset_ln.assign(cols.size(), 0.0);
    stage.strike_u = line.strike_u;
    fit_from(ln(Eigen::all, cols), stage);
    line.strike_u = stage.strike_u;
  }
  return fit_from(ln, line);
}

}  // namespace

const std::vector<double>& line_grid_rad() {
  // -1.5 .. 1.5 rad in steps of 1/80 rad: an upper mode at ten times the lowest's wavenumber moves an
  // eighth of a radian per step.
  static const std::vector<double> grid = [] {
    std::vector<double> g;
    for (int i = -120; i <= 120; ++i) g.push_back(i / 80.0);
    return g;
  }();
  return grid;
}

Eigen::MatrixXd BendingLine::shapes() const {
  const std::vector<double>& grid = line_grid_rad();
  Eigen::MatrixXd out(Eigen::Index(grid.size()), Eigen::Index(ratio.size()));
  for (std::size_t p = 0; p < grid.size(); ++p)
    for (std::size_t n = 0; n < ratio.size(); ++n)
      out(Eigen::Index(p), Eigen::Index(n)) = offset_ln[n] + shape_ln(ratio[n] * grid[p] + phase_rad[n]);
  return out;
}

BendingLine fit_bending_line(const Eigen::MatrixXd& ln, const std::vector<double>& freq_hz) {
  const Eigen::Index strikes = ln.rows(), modes = ln.cols();
  if (strikes == 0 || modes == 0) return {};
  if (freq_hz.size() != std::size_t(modes)) throw std::invalid_argument("fit_bending_line: one frequency per column");
  BendingLine start;  // phases and offsets at zero; each start places the strikes its own way
  const double lowest = *std::min_element(freq_hz.begin(), freq_hz.end());
  for (double f : freq_hz) start.ratio.push_back(std::sqrt(f / lowest));
  start.phase_rad.assign(std::size_t(modes), 0.0);
  start.offset_ln.assign(std::size_t(modes), 0.0);
  // The strikes' first pattern in the lower modes (left singular vector of their double-centred rows)
  // orders them along the line.
  std::vector<Eigen::Index> low;
  for (Eigen::Index n = 0; n < modes; ++n)
    if (start.ratio[std::size_t(n)] <= kStageRatios[0]) low.push_back(n);
  if (low.size() < 2) {
    low.clear();
    for (Eigen::Index n = 0; n < modes; ++n) low.push_back(n);
  }
  Eigen::MatrixXd centred = ln(Eigen::all, low);
  centred = centred.rowwise() - centred.colwise().mean();
  centred = centred.colwise() - centred.rowwise().mean();
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(centred, Eigen::ComputeThinU);
  const Eigen::VectorXd order = svd.matrixU().col(0);
  const double widest = std::max(order.cwiseAbs().maxCoeff(), 1e-12);
  std::vector<std::vector<double>> starts;
  for (double spread : kStartSpreadRad) {
    starts.emplace_back();
    for (Eigen::Index s = 0; s < strikes; ++s) starts.back().push_back(spread * order(s) / widest);
  }
  std::mt19937_64 rng(0x11e5ULL);  // fixed: the same rows always give the same line
  std::uniform_real_distribution<double> U(-0.6, 0.6);
  for (int i = 0; i < kRandomStarts; ++i) {
    starts.emplace_back();
    for (Eigen::Index s = 0; s < strikes; ++s) starts.back().push_back(U(rng));
  }
  BendingLine line;
  double best = std::numeric_limits<double>::infinity();
  for (const std::vector<double>& u : starts) {
    BendingLine trial = start;
    trial.strike_u = u;
    if (const double sse = fit_in_stages(ln, trial); sse < best) {
      best = sse;
      line = trial;
    }
  }
  for (double u : line.strike_u) line.strike_at.push_back(nearest_on_grid(u));
  return line;
}

}  // namespace ms::audit
