// Features CSV reader (on TidyCsv, like every CSV the statistics read) and lambda/c conversion.
#include "analysis/damping/damping_features.hpp"

#include <cmath>
#include <numbers>

#include "synthesis/tidy_csv.hpp"
#include "synthesis/input_error.hpp"

namespace ms {

namespace {

std::vector<DampingFeature> features_from(const TidyCsv& csv) {
  if (!csv.has_column("freq_hz") || !csv.has_column("decay_per_s"))
    csv.column(!csv.has_column("freq_hz") ? "freq_hz" : "decay_per_s");  // throws, naming the columns there are
  const std::size_t col_f = csv.column("freq_hz"), col_d = csv.column("decay_per_s");
  const bool has_sound = csv.has_column("sound"), has_amp = csv.has_column("amp");
  std::vector<DampingFeature> features;
  for (std::size_t r = 0; r < csv.rows(); ++r) {
    DampingFeature f;
    f.line = csv.where(r).line;
    if (has_sound) f.sound = csv.cell(r, csv.column("sound"));
    f.freq_hz = csv.number(r, col_f);
    f.decay_per_s = csv.number(r, col_d);
    if (!(f.freq_hz > 0)) throw InputError(csv.where(r, col_f), "freq_hz must be greater than 0");
    // A measured mode always decays; 0 or negative is an extraction failure (and breaks log-space fits).
    if (!(f.decay_per_s > 0)) throw InputError(csv.where(r, col_d), "decay_per_s must be greater than 0");
    if (has_amp) {
      const std::size_t col_a = csv.column("amp");
      f.amp = csv.number(r, col_a);
      if (f.amp < 0) throw InputError(csv.where(r, col_a), "amp must not be negative");
    }
    features.push_back(f);
  }
  if (features.empty()) throw InputError(SourceLocation{csv.file(), 0, 0}, "features CSV has no rows");
  return features;
}

}  // namespace

std::vector<DampingFeature> parse_damping_features_csv(const std::string& text, const std::string& file) {
  return features_from(TidyCsv::parse(text, file));
}

std::vector<DampingFeature> read_damping_features_csv(const std::string& path) {
  return features_from(TidyCsv::read(path));
}

DampingPoint damping_point(double freq_hz, double decay_per_s) {
  const double omega_d = 2.0 * std::numbers::pi * freq_hz;
  return DampingPoint{omega_d * omega_d + decay_per_s * decay_per_s, 2.0 * decay_per_s};
}

std::vector<DampingPoint> damping_points(const std::vector<DampingFeature>& features) {
  std::vector<DampingPoint> points;
  points.reserve(features.size());
  for (const auto& f : features) points.push_back(damping_point(f.freq_hz, f.decay_per_s));
  return points;
}

}  // namespace ms
