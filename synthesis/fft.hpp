// One-dimensional FFTs over FFTW with owned, aligned buffers: the one place the project makes and
// destroys FFTW plans. FFTW's planner is not thread-safe (stimuli are rendered and analysed on worker
// threads), so every plan is made and destroyed under one process-wide lock; executing a plan needs
// no lock. Plans use FFTW_ESTIMATE: the same size always gives the same plan, hence the same numbers.
#pragma once
#include <complex>
#include <cstddef>
#include <mutex>

namespace ms {

// The lock around FFTW's planner.
std::mutex& fftw_planner_mutex();

// The smallest n >= at_least whose only prime factors are 2, 3, 5 and 7 (sizes FFTW is fast at).
std::size_t nice_fft_size(std::size_t at_least);

// Real <-> half-complex transform of size n: forward() takes real() (n values) to spectrum()
// (n/2 + 1 bins, unnormalised); backward() takes spectrum() back to real() multiplied by n and
// overwrites spectrum() (FFTW's c2r), so it is made only when asked for.
class RealFft {
 public:
  enum class Directions { forward, forward_and_backward };
  explicit RealFft(std::size_t n, Directions directions = Directions::forward);
  ~RealFft();
  RealFft(const RealFft&) = delete;
  RealFft& operator=(const RealFft&) = delete;

  std::size_t size() const { return n_; }
  double* real() { return real_; }
  std::complex<double>* spectrum() { return spectrum_; }
  void forward();
  void backward();

 private:
  std::size_t n_;
  double* real_ = nullptr;
  std::complex<double>* spectrum_ = nullptr;
  void* forward_ = nullptr;   // fftw_plan
  void* backward_ = nullptr;  // fftw_plan, or null
};

// In-place complex transform of size n with the exponent's sign +1 (FFTW_BACKWARD, unnormalised):
// the inverse DFT times n.
class ComplexInverseFft {
 public:
  explicit ComplexInverseFft(std::size_t n);
  ~ComplexInverseFft();
  ComplexInverseFft(const ComplexInverseFft&) = delete;
  ComplexInverseFft& operator=(const ComplexInverseFft&) = delete;

  std::size_t size() const { return n_; }
  std::complex<double>* data() { return data_; }
  void execute();

 private:
  std::size_t n_;
  std::complex<double>* data_ = nullptr;
  void* plan_ = nullptr;  // fftw_plan
};

}  // namespace ms
