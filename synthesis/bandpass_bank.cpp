// BandpassBank: Pd's [bp~] per mode, excited by an impulse, summed and clipped; see bandpass_bank.hpp.
#include "synthesis/bandpass_bank.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ms {

double material_q(BandpassMaterial material, QTable table) {
  const auto i = std::size_t(material);
  if (table == QTable::table_4_1) {
    constexpr double kTable41[] = {1000.0, 1500.0, 3000.0, 3500.0, 4000.0};
    return kTable41[i];
  }
  // 20 .. 5000 in four equal ratios.
  return 20.0 * std::pow(5000.0 / 20.0, double(i) / 4.0);
}

namespace {

// sigbp_qcos: a cosine's Taylor polynomial to the 6th order on [-pi/2, pi/2] (Pd's 3.14159), 0 outside.
float pd_qcos(float f) {
  if (f >= -(0.5f * 3.14159f) && f <= 0.5f * 3.14159f) {
    const float g = f * f;
    return float(((g * g * g * (-1.0f / 720.0f) + g * g * (1.0f / 24.0f)) - g * 0.5) + 1);
  }
  return 0.0f;
}

// PD_BIGORSMALL: a denormal, infinite or NaN state value, which Pd sets to 0 after each block.
float flushed(float v) { return std::isnormal(v) || v == 0.0f ? v : 0.0f; }

}  // namespace

PdBandpassCoefficients pd_bandpass_coefficients(double centre_hz, double q, double sample_rate_hz) {
  float f = float(centre_hz), qf = float(q);
  const float sr = float(sample_rate_hz);
  if (double(f) < 0.001) f = 10.0f;
  if (qf < 0.0f) qf = 0.0f;
  const float omega = f * (2.0f * 3.14159f) / sr;
  float oneminusr = double(qf) < 0.001 ? 1.0f : omega / qf;
  if (oneminusr > 1.0f) oneminusr = 1.0f;
  const float r = 1.0f - oneminusr;
  PdBandpassCoefficients c;
  c.coef1 = 2.0f * pd_qcos(omega) * r;
  c.coef2 = -r * r;
  c.gain = 2.0f * oneminusr * (oneminusr + r * omega);
  return c;
}

BandpassBank::BandpassBank(const ModalModel& model, const std::vector<double>& q, double impulse, double clip,
                           double sample_rate_hz)
    : impulse_(float(impulse)), clip_(float(clip)) {
  if (q.size() != 1 && q.size() != model.modes.size())
    throw std::invalid_argument("band-pass bank: " + std::to_string(q.size()) + " Q values for " +
                                std::to_string(model.modes.size()) + " modes (give one, or one per mode)");
  for (std::size_t n = 0; n < model.modes.size(); ++n) {
    const Mode& m = model.modes[n];
    if (!(m.freq_hz > 0.0 && m.freq_hz < 0.5 * sample_rate_hz)) continue;
    const PdBandpassCoefficients c = pd_bandpass_coefficients(m.freq_hz, q.size() == 1 ? q[0] : q[n], sample_rate_hz);
    coef1_.push_back(c.coef1);
    coef2_.push_back(c.coef2);
    gain_.push_back(c.gain);
    amp_.push_back(float(m.amp));
  }
  last_.assign(coef1_.size(), 0.0f);
  prev_.assign(coef1_.size(), 0.0f);
}

void BandpassBank::render(float* out, std::size_t frames) {
  std::fill(out, out + frames, 0.0f);
  for (std::size_t k = 0; k < coef1_.size(); ++k) {
    const float coef1 = coef1_[k], coef2 = coef2_[k], gain = gain_[k], amp = amp_[k];
    float last = last_[k], prev = prev_[k];
    for (std::size_t i = 0; i < frames; ++i) {
      const std::size_t n = position_ + i;
      const float in = n == 0 ? impulse_ : 0.0f;
      const float w = in + coef1 * last + coef2 * prev;
      out[i] += amp * (gain * w);  // [bp~], then [*~ amp], then [+~] over the filters in order
      prev = last;
      last = w;
      if ((n + 1) % kPdBlockFrames == 0) {
        last = flushed(last);
        prev = flushed(prev);
      }
    }
    last_[k] = last;
    prev_[k] = prev;
  }
  if (clip_ > 0.0f)
    for (std::size_t i = 0; i < frames; ++i) out[i] = std::clamp(out[i], -clip_, clip_);
  position_ += frames;
}

std::vector<float> render_bandpass(const ModalModel& model, const std::vector<double>& q, double impulse,
                                   double clip, double sample_rate_hz, std::size_t frames) {
  BandpassBank bank(model, q, impulse, clip, sample_rate_hz);
  std::vector<float> out(frames);
  bank.render(out.data(), frames);
  return out;
}

}  // namespace ms
