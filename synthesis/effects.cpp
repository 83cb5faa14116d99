#include "synthesis/effects.hpp"

#include <cmath>
#include <random>

namespace ms {

void apply_support_damping(ModalModel& model, const SupportDamping& support) {
  std::mt19937_64 rng(support.seed);
  std::exponential_distribution<double> excess(
      support.exponential_mean_per_s > 0 ? 1.0 / support.exponential_mean_per_s : 1.0);
  for (std::size_t n = 0; n < model.modes.size(); ++n) {
    double add = support.extra_decay_per_s;
    if (n < support.per_mode_decay_per_s.size()) add += support.per_mode_decay_per_s[n];
    if (support.exponential_mean_per_s > 0) add += excess(rng);
    model.modes[n].decay_per_s += add;
  }
}

void apply_doublets(ModalModel& model, const Doublets& doublets, const std::vector<int>& orders) {
  if (doublets.split_rel <= 0 && doublets.split_hz <= 0) return;
  ModalModel out;
  out.hit_point_names = model.hit_point_names;
  out.hit_gains.resize(model.hit_gains.size());
  for (std::size_t n = 0; n < model.modes.size(); ++n) {
    const Mode& m = model.modes[n];
    const bool split = orders.empty() || (n < orders.size() && orders[n] >= doublets.min_order);
    auto copy_gain = [&](std::size_t times) {
      for (std::size_t h = 0; h < model.hit_gains.size(); ++h)
        for (std::size_t k = 0; k < times; ++k)
          out.hit_gains[h].push_back(n < model.hit_gains[h].size() ? model.hit_gains[h][n] : 1.0);
    };
    if (!split) {
      out.modes.push_back(m);
      copy_gain(1);
      continue;
    }
    const double delta = doublets.split_hz > 0 ? doublets.split_hz : doublets.split_rel * m.freq_hz;
    Mode lower = m, upper = m;
    lower.freq_hz = m.freq_hz - 0.5 * delta;
    upper.freq_hz = m.freq_hz + 0.5 * delta;
    lower.amp = (1.0 - doublets.balance) * m.amp;
    upper.amp = doublets.balance * m.amp;
    out.modes.push_back(lower);
    out.modes.push_back(upper);
    copy_gain(2);
  }
  model = std::move(out);
}

void add_background_noise(std::vector<float>& samples, const BackgroundNoise& noise) {
  if (!noise.enabled || samples.empty()) return;
  double power = 0.0;
  for (float v : samples) power += double(v) * v;
  power /= double(samples.size());
  const double sigma = std::sqrt(power / std::pow(10.0, noise.snr_db / 10.0));
  std::mt19937_64 rng(noise.seed);
  std::normal_distribution<double> gauss(0.0, sigma);
  for (float& v : samples) v = float(v + gauss(rng));
}

}  // namespace ms
