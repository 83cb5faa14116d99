// A small protocol on disk for the session, cache and autopilot tests: two one-mode parameter sets,
// a derived anchor and one block of each answered kind.
#pragma once
#include <string>

#include "support/test_util.hpp"

namespace ms::testing {

inline std::string write_small_study(const test::TempDir& dir, const std::string& extra_blocks = "") {
  dir.write("sets/low.yaml",
            "sample_rate: 44100\nduration_s: 0.5\nmodes:\n  - {freq_hz: 440.0, decay_per_s: 6.0, amp: 0.5}\n"
            "  - {freq_hz: 5200.0, decay_per_s: 20.0, amp: 0.3}\nexcitation: {type: impulse}\n"
            "level: {normalize: none}\n");
  dir.write("sets/high.yaml",
            "sample_rate: 44100\nduration_s: 0.5\nmodes:\n  - {freq_hz: 880.0, decay_per_s: 6.0, amp: 0.5}\n"
            "excitation: {type: impulse}\nlevel: {normalize: none}\n");
  return dir.write("study.yaml",
                   "study: small\ntitle: Small\nsample_rate: 44100\nseed: 7\n"
                   "stimuli:\n"
                   "  low:  {paramset: sets/low.yaml}\n"
                   "  high: {paramset: sets/high.yaml}\n"
                   "  lowq: {paramset: sets/low.yaml, set: {amp_scale: 0.5}}\n"
                   "  lp:   {derive: low, lowpass_hz: 3500}\n"
                   "blocks:\n"
                   "  - {type: instructions, id: hello, text: Listen.}\n"
                   "  - {type: identify, id: id, stimuli: [low, high], labels: [low, high], repeats: 2}\n"
                   "  - {type: mushra, id: mu, reference: low, conditions: [lowq, lp]}\n" +
                       extra_blocks);
}

}  // namespace ms::testing
