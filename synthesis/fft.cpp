// FFTW plans with owned buffers under one planner lock; see fft.hpp.
#include "synthesis/fft.hpp"

#include <fftw3.h>

#include <algorithm>

namespace ms {

namespace {

// fftw_complex is double[2], laid out as std::complex<double> (FFTW manual, "Complex numbers").
fftw_complex* as_fftw(std::complex<double>* p) { return reinterpret_cast<fftw_complex*>(p); }

}  // namespace

std::mutex& fftw_planner_mutex() {
  static std::mutex m;
  return m;
}

std::size_t nice_fft_size(std::size_t at_least) {
  for (std::size_t n = std::max<std::size_t>(at_least, 1);; ++n) {
    std::size_t r = n;
    for (std::size_t p : {2, 3, 5, 7})
      while (r % p == 0) r /= p;
    if (r == 1) return n;
  }
}

RealFft::RealFft(std::size_t n, Directions directions) : n_(n) {
  real_ = fftw_alloc_real(n);
  spectrum_ = reinterpret_cast<std::complex<double>*>(fftw_alloc_complex(n / 2 + 1));
  const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
  forward_ = fftw_plan_dft_r2c_1d(int(n), real_, as_fftw(spectrum_), FFTW_ESTIMATE);
  if (directions == Directions::forward_and_backward)
    backward_ = fftw_plan_dft_c2r_1d(int(n), as_fftw(spectrum_), real_, FFTW_ESTIMATE);
}

RealFft::~RealFft() {
  {
    const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    fftw_destroy_plan(static_cast<fftw_plan>(forward_));
    if (backward_) fftw_destroy_plan(static_cast<fftw_plan>(backward_));
  }
  fftw_free(spectrum_);
  fftw_free(real_);
}

void RealFft::forward() { fftw_execute(static_cast<fftw_plan>(forward_)); }

void RealFft::backward() { fftw_execute(static_cast<fftw_plan>(backward_)); }

ComplexInverseFft::ComplexInverseFft(std::size_t n) : n_(n) {
  data_ = reinterpret_cast<std::complex<double>*>(fftw_alloc_complex(n));
  const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
  plan_ = fftw_plan_dft_1d(int(n), as_fftw(data_), as_fftw(data_), FFTW_BACKWARD, FFTW_ESTIMATE);
}

ComplexInverseFft::~ComplexInverseFft() {
  {
    const std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    fftw_destroy_plan(static_cast<fftw_plan>(plan_));
  }
  fftw_free(data_);
}

void ComplexInverseFft::execute() { fftw_execute(static_cast<fftw_plan>(plan_)); }

}  // namespace ms
