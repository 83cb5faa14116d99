// Synthetic "measured" recordings for proving the audit: a random object (modes on a Rayleigh law),
// several strikes of random strength with a faint noise floor, hiding zero, one or two effects of a
// given strength. Strength u in [0, 1] maps each effect to a physical range (weakest at 0).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "analysis/audit/strikes.hpp"
#include "synthesis/modal_model.hpp"

namespace ms::audit {

// Effects the generator can hide (the audit's catalog names).
std::vector<std::string> hideable_effects();

struct GeneratorOptions {
  std::size_t strikes = 5;
  double duration_s = 1.5;
  double sample_rate_hz = 44100.0;
  double pre_roll_s = 0.01;  // silence (faint noise) before each strike
  // Strikes that move: every mode's amplitude in every strike times 10^(jitter_db N(0,1) / 20), drawn
  // from a stream of its own (0: the strikes differ only by their gain and the hidden effects).
  double amplitude_jitter_db = 0.0;
};

struct HiddenCase {
  std::uint64_t seed = 0;
  std::vector<std::string> effects;   // hidden, as asked
  std::vector<double> strengths;      // one per effect, in [0, 1]
  ModalModel object;                  // the clean object (amplitudes at strike gain 1)
  std::vector<double> strike_gain;    // per strike
  std::vector<Recording> recordings;  // "strike1".."strikeN"
  std::string summary;                // one line: what is hidden, with its physical parameters
};

// Throws std::invalid_argument for an unknown effect name or a strength outside [0, 1].
HiddenCase generate_hidden_case(std::uint64_t seed, const std::vector<std::string>& effects,
                                const std::vector<double>& strengths, const GeneratorOptions& options = {});

}  // namespace ms::audit
