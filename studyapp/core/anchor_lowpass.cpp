// lowpass_anchor: one real FFT forward, a gain per bin, one back (FFTW, double precision).
#include "studyapp/core/anchor_lowpass.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <numbers>

#include "analysis/subband.hpp"
#include "studyapp/core/fftw_planner.hpp"

namespace ms {

std::vector<float> lowpass_anchor(const std::vector<float>& samples, double fs, double cutoff_hz) {
  if (samples.empty()) return {};
  // Padding keeps the filter's (short) time response from wrapping the tail onto the attack.
  const std::size_t n = nice_fft_size(samples.size() + samples.size() / 8 + 1024);
  double* buf = fftw_alloc_real(n);
  fftw_complex* spec = fftw_alloc_complex(n / 2 + 1);
  fftw_plan forward, backward;
  {
    const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    forward = fftw_plan_dft_r2c_1d(int(n), buf, spec, FFTW_ESTIMATE);
    backward = fftw_plan_dft_c2r_1d(int(n), spec, buf, FFTW_ESTIMATE);
  }
  std::fill(buf, buf + n, 0.0);
  std::copy(samples.begin(), samples.end(), buf);
  fftw_execute(forward);
  const double width_hz = 0.05 * cutoff_hz, lo = cutoff_hz - width_hz / 2, hi = cutoff_hz + width_hz / 2;
  for (std::size_t k = 0; k <= n / 2; ++k) {
    const double f = double(k) * fs / double(n);
    double g = 1.0;
    if (f >= hi) g = 0.0;
    else if (f > lo) g = 0.5 * (1.0 + std::cos(std::numbers::pi * (f - lo) / width_hz));
    g /= double(n);  // FFTW's inverse is unnormalised
    spec[k][0] *= g;
    spec[k][1] *= g;
  }
  fftw_execute(backward);
  std::vector<float> out(samples.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = float(buf[i]);
  {
    const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    fftw_destroy_plan(forward);
    fftw_destroy_plan(backward);
  }
  fftw_free(spec);
  fftw_free(buf);
  return out;
}

}  // namespace ms
