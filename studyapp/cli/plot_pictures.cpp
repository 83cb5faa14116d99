#include "studyapp/cli/plot_pictures.hpp"

#include <algorithm>
#include <cmath>

#include "analysis/damping/damping_fit.hpp"
#include "analysis/damping/emg_likelihood.hpp"
#include "studyapp/cli/stats_output.hpp"

namespace ms::cli {

using plots::PlotOptions;
using plots::Series;
using plots::XY;

std::vector<XY> sample_law(const DampingLaw& law, double lo, double hi, int n) {
  std::vector<XY> out;
  for (int i = 0; i < n; ++i) {
    const double lambda = lo * std::pow(hi / lo, double(i) / (n - 1));
    out.push_back({lambda, damping_c_per_s(law, lambda)});
  }
  return out;
}

std::vector<std::vector<double>> by_band(const BarkImage& img, std::size_t frames) {
  std::vector<std::vector<double>> out(img.bands, std::vector<double>(frames, 0.0));
  for (std::size_t m = 0; m < img.frames && m < frames; ++m)
    for (std::size_t b = 0; b < img.bands; ++b) out[b][m] = img.at(m, b);
  return out;
}

namespace {

// "%.2g" without the exponent's sign and zero padding (9.6e-06 -> 9.6e-6): legends stay short.
std::string short_g(double v) {
  std::string s = format_g(v, 2);
  const auto e = s.find('e');
  if (e == std::string::npos) return s;
  std::string exponent = s.substr(e + 1);
  const bool negative = exponent[0] == '-';
  exponent.erase(0, exponent.find_first_not_of("+-0"));
  return s.substr(0, e) + "e" + (negative ? "-" : "") + (exponent.empty() ? "0" : exponent);
}

std::string law_summary(const DampingFit& fit) {
  std::string s = to_string(fit.estimator) + ":";
  if (fit.law.kind != DampingKind::powerlaw) s += " α₁=" + short_g(fit.law.alpha1);
  s += " α₂=" + short_g(fit.law.alpha2);
  if (fit.law.kind != DampingKind::rayleigh) s += " α₃=" + short_g(fit.law.alpha3);
  return s;
}

}  // namespace

std::vector<Series> fitted_curves(const std::vector<DampingPoint>& points, DampingKind law) {
  double lo = points.front().lambda_rad2_s2, hi = lo;
  for (const auto& p : points) {
    lo = std::min(lo, p.lambda_rad2_s2);
    hi = std::max(hi, p.lambda_rad2_s2);
  }
  if (hi <= lo) hi = lo * 1.01;
  std::vector<Series> curves;
  for (auto estimator : {DampingEstimator::lsq, DampingEstimator::lb, DampingEstimator::emg}) {
    const DampingFit fit = fit_damping(points, law, estimator);
    curves.push_back({law_summary(fit), sample_law(fit.law, lo, hi)});
  }
  return curves;
}

void plot_masking_model(const ModalModel& model, const PruneResult& r, const std::string& output,
                        const std::string& title) {
  std::vector<double> freq_hz;
  std::vector<bool> kept(model.modes.size(), false);
  for (const auto& m : model.modes) freq_hz.push_back(m.freq_hz);
  for (std::size_t k : r.kept) kept[k] = true;
  PlotOptions o;
  o.title = title;
  plots::masking_plot(output, freq_hz, r.level_db, r.masking_db, r.quiet_db, kept, o);
}

}  // namespace ms::cli
