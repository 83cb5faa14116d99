// Extraction of strikes with a finite contact (the shipped bar stimuli): with the contact skipped,
// every mode comes back; without the dynamic-range floor the noiseless transient would be "explained"
// by hundreds of spurious modes.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "analysis/extraction/feature_extraction.hpp"
#include "synthesis/paramset.hpp"
#include "synthesis/stimulus.hpp"

using namespace ms;

TEST(ExtractionContact, ShippedBarStrikesGiveBackTheirModes) {
  for (const char* set : {"bar/sterling-steel.yaml", "bar/sterling-glass.yaml", "bar/ren-metal.yaml"}) {
    const ParamSet p = load_paramset(std::string(MODALSTUDY_SOURCE_DIR) + "/stimuli/" + set);
    const RenderedStimulus r = render_stimulus(p);
    std::vector<std::string> ignored;
    const ModalModel truth = audible_model(p, ignored);
    ExtractOptions options;
    options.skip_contact_s = 0.0005;  // the bars are struck with a 0.5 ms raised cosine
    const ExtractedFeatures f = extract_features(r.audio.samples, p.sample_rate_hz, options);
    double strongest = 0;
    for (const Mode& m : truth.modes) strongest = std::max(strongest, m.amp * std::abs(
        r.level_gain));
    std::size_t expected = 0, found = 0;
    for (const Mode& t : truth.modes) {
      // Modes a 0.5 ms contact leaves above -60 dB of the strongest, decaying slower than 500 1/s.
      if (t.decay_per_s > 500) continue;
      ++expected;
      for (const Mode& e : f.modes)
        if (std::abs(e.freq_hz - t.freq_hz) < 1e-4 * t.freq_hz &&
            std::abs(e.decay_per_s - t.decay_per_s) < 0.01 * t.decay_per_s) {
          ++found;
          break;
        }
    }
    EXPECT_GE(expected, 4u) << set;
    EXPECT_EQ(found, expected) << set;
    EXPECT_LE(f.modes.size(), truth.modes.size() + 2) << set << ": spurious modes";
  }
}
