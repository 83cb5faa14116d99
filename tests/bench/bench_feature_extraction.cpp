// Speed of extract_features on a 2 s, 44.1 kHz mono impact (40 modes, 40 dB SNR), next to two
// naive references: a single full-length FFT peak-picker and full-band ESPRIT on the first 50 ms.
// Also the error bars (mode_precision) against the textbook way: the Jacobian over every sample; and
// two steps a room recording's fit repeats, each beside the way it was done before.
#include <benchmark/benchmark.h>
#include <fftw3.h>

#include <cmath>
#include <complex>
#include <vector>

#include "../analysis/extraction/extraction_fixtures.hpp"
#include <Eigen/Dense>
#include <numbers>

#include "analysis/extraction/esprit.hpp"
#include "analysis/extraction/feature_extraction.hpp"
#include "analysis/extraction/mode_precision.hpp"
#include "analysis/extraction/noise_envelope.hpp"
#include "analysis/extraction/damped_fit.hpp"
#include "synthesis/effects.hpp"

namespace {

constexpr double kFs = 44100.0;

const std::vector<float>& impact() {
  static const std::vector<float> x = [] {
    ms::ModalModel m = ms::testing::random_impact(7, 40, 40);
    return ms::testing::render_noisy(m, kFs, 2.0, 40.0, 7);
  }();
  return x;
}

// Arg 0: the default pipeline; arg 1: with the low-band second start (extract --thorough).
void BM_ExtractFeatures(benchmark::State& state) {
  const auto& x = impact();
  ms::ExtractOptions options;
  options.low_band_restart = state.range(0) != 0;
  std::size_t modes = 0;
  for (auto _ : state) {
    const auto f = ms::extract_features(x, kFs, options);
    modes = f.modes.size();
    benchmark::DoNotOptimize(modes);
  }
  state.counters["modes"] = double(modes);
}
BENCHMARK(BM_ExtractFeatures)->ArgName("thorough")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// The same impact (20 modes) in a room: a white tail of RT60 0.5 s at -40 dB re the direct sound over
// a floor 90 dB under the peak. Arg 1: weighed against the tail (default); arg 0: against the floor
// only, which takes the tail for hundreds of modes.
void BM_ExtractInARoom(benchmark::State& state) {
  static const std::vector<float> x = [] {
    std::vector<float> y = ms::testing::render_noisy(ms::testing::random_impact(7, 20, 20), kFs, 2.0, 200.0, 7);
    ms::add_reverb_and_transient(y, kFs, {0.5, -40.0, 7, true}, {});
    return y;
  }();
  ms::ExtractOptions options;
  options.room_tail = state.range(0) != 0;
  std::size_t modes = 0;
  for (auto _ : state) {
    modes = ms::extract_features(x, kFs, options).modes.size();
    benchmark::DoNotOptimize(modes);
  }
  state.counters["modes"] = double(modes);
}
BENCHMARK(BM_ExtractInARoom)->ArgName("room_tail")->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);

// Naive reference: one full-length FFT, local maxima above the median level (no decay estimate).
void BM_NaiveFftPeakPicker(benchmark::State& state) {
  const auto& x = impact();
  const int n = int(x.size());
  double* in = fftw_alloc_real(std::size_t(n));
  fftw_complex* out = fftw_alloc_complex(std::size_t(n / 2 + 1));
  fftw_plan plan = fftw_plan_dft_r2c_1d(n, in, out, FFTW_ESTIMATE);
  std::size_t peaks = 0;
  for (auto _ : state) {
    for (int i = 0; i < n; ++i) in[i] = x[std::size_t(i)];
    fftw_execute(plan);
    std::vector<double> mag(std::size_t(n / 2 + 1));
    for (std::size_t k = 0; k < mag.size(); ++k) mag[k] = std::hypot(out[k][0], out[k][1]);
    std::vector<double> sorted = mag;
    std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(sorted.size() / 2), sorted.end());
    const double floor = 30.0 * sorted[sorted.size() / 2];
    peaks = 0;
    for (std::size_t k = 1; k + 1 < mag.size(); ++k)
      if (mag[k] > floor && mag[k] > mag[k - 1] && mag[k] >= mag[k + 1]) ++peaks;
    benchmark::DoNotOptimize(peaks);
  }
  state.counters["peaks"] = double(peaks);
  fftw_destroy_plan(plan);
  fftw_free(out);
  fftw_free(in);
}
BENCHMARK(BM_NaiveFftPeakPicker)->Unit(benchmark::kMillisecond);

// Reference: full-band ESPRIT (analytic signal not needed: real data, 2 poles per mode) on 50 ms.
void BM_FullBandEsprit50ms(benchmark::State& state) {
  const auto& x = impact();
  std::vector<std::complex<double>> y(std::size_t(0.05 * kFs));
  for (std::size_t i = 0; i < y.size(); ++i) y[i] = x[i];
  ms::EspritOptions eo;
  eo.window = 240;
  eo.max_order = 120;
  eo.noise_power = 1e-6;
  std::size_t poles = 0;
  for (auto _ : state) {
    poles = ms::esprit(y.data(), y.size(), eo).size();
    benchmark::DoNotOptimize(poles);
  }
  state.counters["poles"] = double(poles);
}
BENCHMARK(BM_FullBandEsprit50ms)->Unit(benchmark::kMillisecond);

}  // namespace

// A model's modes as the extraction's components (amplitude at n = 0, phase so that Re gives a sine).
std::vector<ms::DampedComponent> components_of(const ms::ModalModel& model) {
  std::vector<ms::DampedComponent> c;
  for (const ms::Mode& m : model.modes)
    c.push_back({std::complex<double>(-m.decay_per_s, 2.0 * std::numbers::pi * m.freq_hz) / kFs,
                 std::complex<double>(0.0, -m.amp)});
  return c;
}

// The 40 true modes of the impact as components over its 2 s.
std::vector<ms::DampedComponent> impact_components() { return components_of(ms::testing::random_impact(7, 40, 40)); }

// Cramer-Rao bounds from the closed-form Gram (no pass over the samples) and a Cholesky inverse.
void BM_ModePrecision(benchmark::State& state) {
  const auto c = impact_components();
  for (auto _ : state) benchmark::DoNotOptimize(ms::mode_precision(c, std::size_t(2.0 * kFs), kFs, 1e-3).data());
  state.counters["modes"] = double(c.size());
}
BENCHMARK(BM_ModePrecision)->Unit(benchmark::kMillisecond);

// Reference: the Jacobian (4 columns per mode) evaluated at every sample, J^T J by Eigen's GEMM,
// then the same inverse. Same numbers to rounding, far more work.
void BM_ModePrecisionJacobian(benchmark::State& state) {
  const auto c = impact_components();
  const auto N = Eigen::Index(2.0 * kFs), P = Eigen::Index(4 * c.size());
  for (auto _ : state) {
    Eigen::MatrixXd J(N, P);
    for (std::size_t k = 0; k < c.size(); ++k)
      for (Eigen::Index n = 0; n < N; ++n) {
        const std::complex<double> e = std::exp(c[k].s * double(n)), be = c[k].b * e * double(n);
        J(n, Eigen::Index(4 * k)) = e.real();
        J(n, Eigen::Index(4 * k + 1)) = -e.imag();
        J(n, Eigen::Index(4 * k + 2)) = be.real();
        J(n, Eigen::Index(4 * k + 3)) = -be.imag();
      }
    const Eigen::MatrixXd A = J.transpose() * J;
    const Eigen::VectorXd d = A.llt().solve(Eigen::MatrixXd::Identity(P, P)).diagonal();
    benchmark::DoNotOptimize(d.data());
  }
  state.counters["modes"] = double(c.size());
}
BENCHMARK(BM_ModePrecisionJacobian)->Unit(benchmark::kMillisecond);

// A room recording's fit holds well over a hundred components (the room's answer to each mode):
// 136 components over a 2 s strike in a room (RT60 0.5 s, -20 dB), as the extraction meets them.
struct RoomFit {
  std::vector<double> signal;
  std::vector<ms::DampedComponent> comps;
  ms::NoiseEnvelope tail;
};
const RoomFit& room_fit() {
  static const RoomFit f = [] {
    RoomFit r;
    const ms::ModalModel m = ms::testing::random_impact(11, 136, 136);
    std::vector<float> y = ms::testing::render_noisy(m, kFs, 2.0, 200.0, 11);
    ms::add_reverb_and_transient(y, kFs, {0.5, -20.0, 11, true}, {});
    r.signal.assign(y.begin(), y.end());
    r.comps = components_of(m);
    r.tail = ms::estimate_noise_envelope(r.signal, kFs, 1e-10);
    return r;
  }();
  return f;
}

// Whether each component is worth its place under the tail (its weighted fit gain). Arg 1: eight
// components per pass over the samples (ours); arg 0: one pass per component.
void BM_WeightedFitGains(benchmark::State& state) {
  const RoomFit& f = room_fit();
  for (auto _ : state) {
    if (state.range(0) != 0) {
      benchmark::DoNotOptimize(f.tail.weighted_fit_gains(f.signal, f.comps).data());
    } else {
      double sum = 0.0;
      for (const auto& c : f.comps) sum += f.tail.weighted_fit_gain(f.signal, c);
      benchmark::DoNotOptimize(sum);
    }
  }
  state.counters["components"] = double(f.comps.size());
}
BENCHMARK(BM_WeightedFitGains)->ArgName("batched")->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);

// One damped Gauss-Newton step of the joint fit: solve (A + lambda diag A) delta = g for the pole Gram
// of those 136 components (544 columns). Arg 0: LDLT in a workspace kept over the steps (ours); arg 1:
// LDLT on a fresh matrix per step (before); arg 2: blocked Cholesky in the workspace (faster, but it
// rounds differently, and the fit's results are tuned on LDLT's).
void BM_JointFitStep(benchmark::State& state) {
  const RoomFit& f = room_fit();
  const Eigen::MatrixXd A = ms::pole_gram(f.comps, f.signal.size());
  const Eigen::VectorXd g = Eigen::VectorXd::Ones(A.rows());
  Eigen::MatrixXd L;
  for (auto _ : state) {
    if (state.range(0) == 0) {
      L = A;
      L.diagonal() += 1e-3 * A.diagonal();
      const Eigen::LDLT<Eigen::Ref<Eigen::MatrixXd>> ldlt(L);
      benchmark::DoNotOptimize(ldlt.solve(g).eval().data());
    } else if (state.range(0) == 1) {
      Eigen::MatrixXd M = A;
      M.diagonal() += 1e-3 * A.diagonal();
      benchmark::DoNotOptimize(M.ldlt().solve(g).eval().data());
    } else {
      L = A;
      L.diagonal() += 1e-3 * A.diagonal();
      const Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> llt(L);
      benchmark::DoNotOptimize(llt.solve(g).eval().data());
    }
  }
  state.counters["columns"] = double(A.rows());
}
BENCHMARK(BM_JointFitStep)->ArgName("solver")->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
