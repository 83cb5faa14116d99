// A parameter set's modes as the audit's baseline; see given_model.hpp.
#include "analysis/audit/given_model.hpp"

#include <cmath>
#include <complex>
#include <vector>

#include "analysis/audit/strikes.hpp"
#include "synthesis/excitation.hpp"
#include "synthesis/stimulus.hpp"

namespace ms::audit {

ModalModel given_model(const ParamSet& set, const std::string& set_path, double recordings_rate_hz) {
  if (set.sample_rate_hz != recordings_rate_hz)
    throw AuditError(set_path + ": sample rate " + std::to_string(std::lround(set.sample_rate_hz)) +
                     " Hz differs from the recordings' " + std::to_string(std::lround(recordings_rate_hz)) + " Hz");
  std::vector<std::string> warnings;
  ModalModel model = audible_model(set, warnings);
  for (Mode& m : model.modes)
    m.amp *= set.excitation.gain * std::abs(contact_factor(set.excitation, m.decay_per_s, m.freq_hz));
  return model;
}

}  // namespace ms::audit
