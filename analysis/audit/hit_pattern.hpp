// Strikes that move: where a strike lands sets how strongly each mode sounds (the mode shape at the hit
// point), so from strike to strike the modes' amplitudes change by more than a common gain. The pattern
// multiplies mode n's amplitude in strike s by exp(l[s][n]), l in natural-log units, from one of:
//  - an object's mode shapes: l[s][n] = shape_ln[p_s][n], p_s the strike's hit position on a grid;
//  - a low-rank pattern (no geometry known): l[s][n] = sum_k coord[s][k] loading[n][k];
//  - a path through the strikes (no geometry known, the hit point moving along a line the mode shapes
//    bend): the same sum, its loadings the training strikes' own patterns and each strike's weights
//    placing it on or between two of them (weights summing to 1);
//  - a bending-wave line learnt from the strikes (bending_line.hpp): like an object's shapes, on the
//    line's grid of coordinates.
#pragma once
#include <cstddef>
#include <vector>

namespace ms::audit {

struct HitPattern {
  // Low rank: loading[n][k] (mode n's response to pattern k), coord[s][k] (strike s's weight of it).
  std::vector<std::vector<double>> loading;
  std::vector<std::vector<double>> coord;
  bool on_path = false;  // the loadings are the training strikes' patterns; a strike sits between two
  // Object: the hit positions of the grid (fraction of the length or radius), the log amplitude of
  // every mode at each relative to the parameter set's own hit, and each strike's fitted position.
  // A learnt line fills the same fields: its coordinates (radians of the lowest mode's shape) and shapes.
  std::vector<double> positions;
  std::vector<std::vector<double>> shape_ln;  // [position][mode]
  std::vector<std::size_t> strike_position;   // per strike, index into positions
  // An object's: the parameter set's own hit (its row is all 0); a learnt line's: the grid's middle,
  // where a strike sits before it is placed.
  std::size_t home_position = 0;
  bool learnt_line = false;  // positions and shape_ln learnt from the strikes, not given by an object

  bool from_object() const { return !shape_ln.empty() && !learnt_line; }
  bool active() const { return !coord.empty() || !strike_position.empty(); }
  std::size_t rank() const { return loading.empty() ? 0 : loading.front().size(); }
  // l[s][n] (0 where the pattern says nothing about strike s or mode n).
  double log_factor(std::size_t strike, std::size_t mode) const;
};

// An object's mode shapes for the hit_position effect: for each grid position, each model mode's
// amplitude there relative to where the parameter set strikes it (natural log, clamped at a node).
struct ObjectShapes {
  std::vector<double> positions;
  std::vector<std::vector<double>> shape_ln;  // [position][mode of the given model]
  std::size_t home_position = 0;
};

}  // namespace ms::audit
