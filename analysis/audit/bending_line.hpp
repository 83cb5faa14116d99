// A hit point that moves along a line of an object whose modes are bending waves. A bending wave's
// wavenumber grows as the square root of its frequency, so along the line mode n's shape is
// sin(k_n x + theta_n) with k_n = k_1 sqrt(f_n / f_1): one unknown coordinate per strike
// (u = k_1 x, radians of the lowest mode's shape) places every mode at once, however far the upper
// modes' shapes bend between strikes. A mode's log amplitude at u is
//   offset_n + ln(floor + |sin(sqrt(f_n / f_1) u + theta_n)|),
// the floor because a strike is a patch, not a point: at a node a mode keeps about a tenth of what it
// has at an antinode. Learnt from a few strikes' log-amplitude residuals, with no geometry given.
#pragma once
#include <Eigen/Dense>
#include <vector>

namespace ms::audit {

struct BendingLine {
  std::vector<double> ratio;            // sqrt(f_n / f_1) per mode (column)
  std::vector<double> phase_rad;        // theta_n per mode
  std::vector<double> offset_ln;        // offset_n per mode
  std::vector<double> strike_u;         // per fitted row: its coordinate (radians of the lowest mode)
  std::vector<std::size_t> strike_at;   // per fitted row: the nearest point of line_grid_rad()

  // Log amplitude of every mode at each point of line_grid_rad(): points x modes.
  Eigen::MatrixXd shapes() const;
};

// The coordinates a strike may take (radians of the lowest mode's shape), one grid for every line.
const std::vector<double>& line_grid_rad();

// The line that best explains rows of log-amplitude residuals (strikes x modes, natural log) by each
// strike's gain plus the line's shape at the strike's coordinate, least squares; freq_hz per column.
BendingLine fit_bending_line(const Eigen::MatrixXd& ln, const std::vector<double>& freq_hz);

}  // namespace ms::audit
