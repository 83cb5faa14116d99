#include "synthesis/resonator_bank.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstring>
#include <numbers>

#if defined(__SSE__)
#include <xmmintrin.h>
#endif

namespace ms {

namespace {

constexpr std::size_t kWidth = 8;
using v8f = float __attribute__((vector_size(32)));

// Decayed modes reach denormals; flush them to zero while rendering (restored afterwards).
struct FlushDenormals {
#if defined(__SSE__)
  unsigned saved = _mm_getcsr();
  FlushDenormals() { _mm_setcsr(saved | 0x8040); }  // FTZ | DAZ
  ~FlushDenormals() { _mm_setcsr(saved); }
#endif
};

// 8-point Gauss-Legendre on [0, 1] for the per-sample contact integral.
constexpr std::array<double, 4> kX = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                      0.9602898564975363};
constexpr std::array<double, 4> kW = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                      0.1012285362903763};

// K vectors of 8 modes advanced together over `count` samples; lane sums go to lanes[n*8..].
template <int K>
inline void advance_group(float* re, float* im, const float* c, const float* s, float* lanes,
                          std::size_t count) {
  v8f r[K], i[K], cc[K], ss[K];
  for (int k = 0; k < K; ++k) {
    std::memcpy(&r[k], re + k * kWidth, sizeof(v8f));
    std::memcpy(&i[k], im + k * kWidth, sizeof(v8f));
    std::memcpy(&cc[k], c + k * kWidth, sizeof(v8f));
    std::memcpy(&ss[k], s + k * kWidth, sizeof(v8f));
  }
  for (std::size_t n = 0; n < count; ++n) {
    v8f sum = i[0];
    for (int k = 1; k < K; ++k) sum += i[k];
    v8f acc;
    std::memcpy(&acc, lanes + n * kWidth, sizeof(v8f));
    acc += sum;
    std::memcpy(lanes + n * kWidth, &acc, sizeof(v8f));
    for (int k = 0; k < K; ++k) {
      const v8f nr = cc[k] * r[k] - ss[k] * i[k];
      const v8f ni = ss[k] * r[k] + cc[k] * i[k];
      r[k] = nr;
      i[k] = ni;
    }
  }
  for (int k = 0; k < K; ++k) {
    std::memcpy(re + k * kWidth, &r[k], sizeof(v8f));
    std::memcpy(im + k * kWidth, &i[k], sizeof(v8f));
  }
}

}  // namespace

ResonatorBank::ResonatorBank(const ModalModel& model, const Excitation& excitation,
                             double sample_rate_hz) {
  mode_count_ = model.modes.size();
  padded_ = (mode_count_ + kWidth - 1) / kWidth * kWidth;
  anchor_re_.assign(padded_, 0.0);
  anchor_im_.assign(padded_, 0.0);
  step_re_.assign(padded_, 0.0);
  step_im_.assign(padded_, 0.0);
  re_.assign(padded_, 0.0f);
  im_.assign(padded_, 0.0f);
  c_.assign(padded_, 0.0f);
  s_.assign(padded_, 0.0f);
  lanes_.assign(kBlockFrames * kWidth, 0.0f);

  const double T = 1.0 / sample_rate_hz;
  const bool impulse = excitation.shape == PulseShape::impulse || excitation.contact_s <= 0.0;
  // Samples n = 0 .. contact_frames-1 lie inside the contact and are computed exactly.
  const std::size_t contact_frames =
      impulse ? 0 : std::size_t(std::floor(excitation.contact_s * sample_rate_hz)) + 1;
  head_.assign(contact_frames, 0.0);
  // Force at the Gauss nodes of each sample interval, shared by all modes.
  std::vector<std::array<double, 8>> force_nodes(contact_frames);
  for (std::size_t n = 1; n < contact_frames; ++n)
    for (std::size_t q = 0; q < 8; ++q) {
      const double x = q < 4 ? 0.5 - 0.5 * kX[q] : 0.5 + 0.5 * kX[q - 4];
      force_nodes[n - 1][q] = excitation.force((double(n - 1) + x) * T);
    }

  for (std::size_t m = 0; m < mode_count_; ++m) {
    const Mode& mode = model.modes[m];
    const std::complex<double> p(-mode.decay_per_s, 2.0 * std::numbers::pi * mode.freq_hz);
    const std::complex<double> g = excitation.gain * std::polar(mode.amp, mode.phase_rad);
    const std::complex<double> pole = std::exp(p * T);
    std::complex<double> z = g;  // state at sample 0 for the impulse: y[0] = Im g
    if (!impulse) {
      // I(nT) accumulated sample by sample; y[n] = Im(g e^{p nT} I(nT)).
      std::array<std::complex<double>, 8> node_phase;  // e^{-p x T} at each node offset x
      for (std::size_t q = 0; q < 8; ++q) {
        const double x = q < 4 ? 0.5 - 0.5 * kX[q] : 0.5 + 0.5 * kX[q - 4];
        node_phase[q] = std::exp(-p * (x * T));
      }
      std::complex<double> integral = 0.0, back = 1.0;  // back = e^{-p (n-1) T}
      std::complex<double> forward = 1.0;              // e^{p n T}
      for (std::size_t n = 0; n < contact_frames; ++n) {
        if (n > 0) {
          std::complex<double> piece = 0.0;
          for (std::size_t q = 0; q < 8; ++q)
            piece += kW[q % 4] * 0.5 * force_nodes[n - 1][q] * node_phase[q];
          integral += piece * back * T;
          back /= pole;
        }
        head_[n] += std::imag(g * forward * integral);
        forward *= pole;
      }
      // Complete the contact integral up to tau, then propagate to sample contact_frames.
      const std::complex<double> full = contact_integral(excitation, p, excitation.contact_s);
      z = g * full * forward;  // forward = e^{p * contact_frames * T}
    }
    anchor_re_[m] = z.real();
    anchor_im_[m] = z.imag();
    const std::complex<double> step = std::exp(p * (T * double(kBlockFrames)));
    step_re_[m] = step.real();
    step_im_[m] = step.imag();
    c_[m] = float(pole.real());
    s_[m] = float(pole.imag());
  }
}

void ResonatorBank::start_block() {
  for (std::size_t m = 0; m < padded_; ++m) {
    re_[m] = float(anchor_re_[m]);
    im_[m] = float(anchor_im_[m]);
    const double ar = anchor_re_[m] * step_re_[m] - anchor_im_[m] * step_im_[m];
    const double ai = anchor_re_[m] * step_im_[m] + anchor_im_[m] * step_re_[m];
    anchor_re_[m] = ar;
    anchor_im_[m] = ai;
  }
}

void ResonatorBank::run_block(float* out, std::size_t count) {
  std::fill(lanes_.begin(), lanes_.begin() + count * kWidth, 0.0f);
  std::size_t m = 0;
  constexpr std::size_t kGroup = 4 * kWidth;
  for (; m + kGroup <= padded_; m += kGroup)
    advance_group<4>(&re_[m], &im_[m], &c_[m], &s_[m], lanes_.data(), count);
  for (; m < padded_; m += kWidth)
    advance_group<1>(&re_[m], &im_[m], &c_[m], &s_[m], lanes_.data(), count);
  for (std::size_t n = 0; n < count; ++n) {
    const float* l = &lanes_[n * kWidth];
    out[n] = ((l[0] + l[1]) + (l[2] + l[3])) + ((l[4] + l[5]) + (l[6] + l[7]));
  }
}

void ResonatorBank::render(float* out, std::size_t frames) {
  FlushDenormals guard;
  std::size_t done = 0;
  while (done < frames && position_ < head_.size()) {
    out[done++] = float(head_[position_++]);
  }
  while (done < frames) {
    if (block_offset_ == 0) start_block();
    const std::size_t count = std::min(frames - done, kBlockFrames - block_offset_);
    run_block(out + done, count);
    done += count;
    position_ += count;
    block_offset_ = (block_offset_ + count) % kBlockFrames;
  }
}

std::vector<float> render_bank(const ModalModel& model, const Excitation& excitation,
                               double sample_rate_hz, std::size_t frames) {
  ResonatorBank bank(model, excitation, sample_rate_hz);
  std::vector<float> out(frames);
  bank.render(out.data(), frames);
  return out;
}

}  // namespace ms
