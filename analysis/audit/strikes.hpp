// The measured side of an audit: each recording cut at its onset to a common length, its modal
// features and its Bark spectrogram; and the checks that refuse input an audit cannot answer.
#pragma once
#include <stdexcept>
#include <string>
#include <vector>

#include "analysis/audit/gap_metric.hpp"
#include "analysis/extraction/feature_extraction.hpp"

namespace ms::audit {

// Input the audit cannot answer (message is one line, names the recording when there is one).
class AuditError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Recording {
  std::string name;
  double sample_rate_hz = 0.0;
  std::vector<float> samples;  // mono
};

struct Strike {
  std::string name;
  std::vector<float> samples;  // from the onset, common length
  ExtractedFeatures features;
  double attack_noise_s = 0.0;  // how long after the contact the extraction found noise no mode explains
  Spectra spectra;
};

struct StrikeOptions {
  double max_duration_s = 2.0;    // analysed span after the onset
  double min_duration_s = 0.1;
  // Extraction's dynamic range (ExtractOptions::max_dynamic_range_db). Cutting it to the gap's 60 dB
  // floor would save time on real recordings but loses the faint high modes a soft strike with a long
  // contact still has, which the contact fit needs (tuning seeds).
  double dynamic_range_db = 90.0;
  double skip_contact_s = 0.5e-3; // real strikes have a contact (see ExtractOptions)
  double max_attack_skip_s = 20e-3; // ... and attack noise the modes cannot explain (see ExtractOptions)
};

struct MeasuredStrikes {
  double sample_rate_hz = 0.0;
  Grids grids;
  std::vector<Strike> strikes;
};

// Throws AuditError: no recordings, different sample rates, silent/clipped/too short recordings,
// recordings with no modes above the noise.
MeasuredStrikes prepare_strikes(const std::vector<Recording>& recordings, const StrikeOptions& options = {});

}  // namespace ms::audit
