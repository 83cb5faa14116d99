#include "studyapp/core/stimulus_checks.hpp"

#include <cstdio>
#include <filesystem>

#include "synthesis/audio_file.hpp"
#include "synthesis/input_error.hpp"

namespace ms {

namespace {

std::string number_text(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

}  // namespace

std::string resolve_protocol_path(const Protocol& protocol, const std::string& path) {
  const std::filesystem::path p(path);
  return (p.is_absolute() ? p : std::filesystem::path(protocol.base_dir) / p).lexically_normal().string();
}

void stimulus_file_problem(const StimulusSource& s, const std::string& problem) {
  throw InputError(s.path_where, "stimulus '" + s.name + "': '" + s.path + "': " + problem);
}

std::string confined_stimulus_path(const Protocol& protocol, const StimulusSource& s, const Confinement& confinement) {
  if (const std::string outside = confinement.problem(s.path, protocol.base_dir); !outside.empty())
    throw InputError(s.path_where, "stimulus '" + s.name + "': " + outside);
  return resolve_protocol_path(protocol, s.path);
}

void check_paramset_stimulus(const Protocol& protocol, const StimulusSource& s, const ParamSet& set) {
  if (set.sample_rate_hz != protocol.sample_rate_hz)
    throw InputError(s.path_where, "stimulus '" + s.name + "': parameter set renders at " +
                                       number_text(set.sample_rate_hz) + " Hz but the protocol's sample_rate is " +
                                       number_text(protocol.sample_rate_hz));
}

std::vector<float> read_recording_stimulus(const Protocol& protocol, const StimulusSource& s,
                                           const Confinement& confinement) {
  const std::string path = confined_stimulus_path(protocol, s, confinement);
  Audio a;
  try {
    a = read_audio(path);
  } catch (const InputError& e) {
    stimulus_file_problem(s, e.problem());
  }
  if (a.sample_rate_hz != protocol.sample_rate_hz)
    throw InputError(s.path_where, "stimulus '" + s.name + "': recording '" + s.path + "' is at " +
                                       number_text(a.sample_rate_hz) + " Hz but the protocol's sample_rate is " +
                                       number_text(protocol.sample_rate_hz));
  return mono(a);
}

}  // namespace ms
