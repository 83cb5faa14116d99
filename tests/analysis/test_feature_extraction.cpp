// Accuracy of extract_features on 12 seeded random synthetic impacts (20-60 modes, 44.1 kHz, 2 s,
// white noise 40 dB under the mean power of the WHOLE clean signal). A true mode within 40 dB of the
// strongest counts as found when the nearest extracted mode is within max(1 Hz, 0.5 %); errors are
// pooled over the found modes of all seeds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "analysis/feature_extraction.hpp"
#include "extraction_fixtures.hpp"

namespace ms {
namespace {

constexpr double kFs = 44100.0;

double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  const std::size_t h = v.size() / 2;
  return v.size() % 2 ? v[h] : 0.5 * (v[h - 1] + v[h]);
}

const Mode* nearest(const std::vector<Mode>& found, double freq_hz) {
  const Mode* best = nullptr;
  for (const auto& m : found)
    if (!best || std::abs(m.freq_hz - freq_hz) < std::abs(best->freq_hz - freq_hz)) best = &m;
  return best;
}

bool matches(const Mode* m, double freq_hz) {
  return m && std::abs(m->freq_hz - freq_hz) <= std::max(1.0, 0.005 * freq_hz);
}

TEST(FeatureExtraction, RandomImpactsAt40dBSnr) {
  std::size_t eligible = 0, found = 0, extracted = 0;
  std::vector<double> freq_err, decay_err, amp_err;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const ModalModel truth = testing::random_impact(seed);
    const auto x = testing::render_noisy(truth, kFs, 2.0, 40.0, seed);
    const ExtractedFeatures got = extract_features(x, kFs);
    extracted += got.modes.size();
    double strongest = 0.0;
    for (const auto& m : truth.modes) strongest = std::max(strongest, m.amp);
    std::size_t case_found = 0, case_eligible = 0;
    for (const auto& m : truth.modes) {
      if (m.amp < strongest * 0.01) continue;  // within 40 dB of the strongest
      ++case_eligible;
      const Mode* e = nearest(got.modes, m.freq_hz);
      if (!matches(e, m.freq_hz)) {
        std::printf("  seed %d missed f=%.1f d=%.2f a=%.4g (nearest %.1f d %.1f)\n", int(seed), m.freq_hz,
                    m.decay_per_s, m.amp, e ? e->freq_hz : 0.0, e ? e->decay_per_s : 0.0);
        continue;
      }
      ++case_found;
      freq_err.push_back(std::abs(e->freq_hz - m.freq_hz) / m.freq_hz);
      decay_err.push_back(std::abs(e->decay_per_s - m.decay_per_s) / m.decay_per_s);
      amp_err.push_back(std::abs(e->amp - m.amp) / m.amp);
    }
    std::printf("seed %d: %zu/%zu found, %zu extracted, noise %.1f dB\n", int(seed), case_found,
                case_eligible, got.modes.size(), got.noise_floor_db);
    eligible += case_eligible;
    found += case_found;
  }
  const double recall = double(found) / double(eligible);
  std::printf("recall %.4f (%zu/%zu), extracted %zu, median rel err: freq %.3g decay %.3g amp %.3g\n",
              recall, found, eligible, extracted, median(freq_err), median(decay_err), median(amp_err));
  // Goal (issue 3): >= 0.95. Not reached yet: heavily damped (d > 100 1/s) modes crowded below
  // ~300 Hz are still missed (0.874 measured on these 12 seeds). This bound guards the level reached.
  EXPECT_GE(recall, 0.85);
  EXPECT_LE(median(freq_err), 0.0005);
  EXPECT_LE(median(decay_err), 0.03);
  EXPECT_LE(median(amp_err), 0.05);
  // Few spurious features: the extracted count stays close to the true count.
  EXPECT_LE(double(extracted), 1.15 * double(eligible));
}

}  // namespace
}  // namespace ms
