// Median-periodogram noise estimate (FFTW); see noise_floor.hpp.
#include "analysis/noise_floor.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "analysis/subband.hpp"

namespace ms {

double estimate_noise_sigma(const std::vector<double>& x) {
  const std::size_t n = std::max<std::size_t>(std::min<std::size_t>(x.size(), 64), x.size() / 4);
  if (n < 16) return 0.0;
  const std::size_t size = nice_fft_size(n), start = x.size() - n;
  double* in = fftw_alloc_real(size);
  fftw_complex* out = fftw_alloc_complex(size / 2 + 1);
  fftw_plan plan = fftw_plan_dft_r2c_1d(int(size), in, out, FFTW_ESTIMATE);
  std::fill(in, in + size, 0.0);
  double window_energy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double w = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * (double(i) + 0.5) / double(n));
    in[i] = w * x[start + i];
    window_energy += w * w;
  }
  fftw_execute(plan);
  // Interior bins only: 0 Hz and Nyquist are chi-square with one degree of freedom.
  std::vector<double> power;
  power.reserve(size / 2);
  for (std::size_t k = 1; k < size / 2; ++k) power.push_back(out[k][0] * out[k][0] + out[k][1] * out[k][1]);
  fftw_destroy_plan(plan);
  fftw_free(out);
  fftw_free(in);
  auto mid = power.begin() + std::ptrdiff_t(power.size() / 2);
  std::nth_element(power.begin(), mid, power.end());
  return std::sqrt(*mid / (std::numbers::ln2 * window_energy));
}

double noise_floor_db(double sigma) { return sigma > 0.0 ? 20.0 * std::log10(sigma) : -400.0; }

}  // namespace ms
