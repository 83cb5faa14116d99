// Damping features: per-mode (freq_hz, decay_per_s) measured on many strikes of one material, read from
// a features CSV (`sound,freq_hz,decay_per_s,amp`; sound and amp optional) and turned into the
// (lambda, c) points the damping-law fit works on: lambda = omega_d^2 + d^2, c = 2 d (Sterling 2019).
#pragma once
#include <string>
#include <vector>

namespace ms {

struct DampingFeature {
  std::string sound;         // strike/recording id ("" when the column is absent)
  double freq_hz = 0.0;      // damped frequency f_d
  double decay_per_s = 0.0;  // amplitude decay rate d
  double amp = 0.0;          // 0 when the column is absent
  int line = 0;              // 1-based line in the CSV, for messages
};

// One point of the fit: eigenvalue and Sterling's damping value.
struct DampingPoint {
  double lambda_rad2_s2 = 0.0;  // lambda = omega^2 = omega_d^2 + d^2, undamped (rad/s)^2
  double c_per_s = 0.0;         // c = 2 d
};

// Header must name freq_hz and decay_per_s (any order; sound, amp optional; others ignored).
// Errors (InputError) name file:line:column: missing column, non-numeric/NaN/inf cell,
// freq_hz <= 0, decay_per_s <= 0, negative amp, wrong cell count, no rows.
std::vector<DampingFeature> parse_damping_features_csv(const std::string& text, const std::string& file);
std::vector<DampingFeature> read_damping_features_csv(const std::string& path);

// lambda = (2 pi f_d)^2 + d^2 inverts f_d = sqrt(lambda - d^2)/2pi exactly; c = 2 d.
DampingPoint damping_point(double freq_hz, double decay_per_s);
std::vector<DampingPoint> damping_points(const std::vector<DampingFeature>& features);

}  // namespace ms
