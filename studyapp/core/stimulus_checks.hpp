// The checks a stimulus must pass before a session can use it. The stimulus cache makes them when a
// session starts and the validator (protocol check) makes the same ones, so that check and start
// agree. Each throws InputError at the stimulus's path in the protocol (file:line:column).
#pragma once
#include <string>
#include <vector>

#include "studyapp/core/protocol.hpp"
#include "synthesis/paramset.hpp"
#include "synthesis/path_confinement.hpp"

namespace ms {

// Absolute path of a protocol's stimulus file or parameter set (relative to the protocol's folder).
std::string resolve_protocol_path(const Protocol& protocol, const std::string& path);

// The absolute path of the file a stimulus names, which must lie inside `confinement` (the
// protocol's: protocol_confinement).
std::string confined_stimulus_path(const Protocol& protocol, const StimulusSource& s, const Confinement& confinement);

// A parameter set must render at the protocol's sample rate.
void check_paramset_stimulus(const Protocol& protocol, const StimulusSource& s, const ParamSet& set);

// A recording: inside the confinement, a regular audio file within the size caps, finite samples,
// at the protocol's sample rate; mixed to mono.
std::vector<float> read_recording_stimulus(const Protocol& protocol, const StimulusSource& s,
                                           const Confinement& confinement);

// A problem of the file a stimulus names, reported at its path in the protocol.
[[noreturn]] void stimulus_file_problem(const StimulusSource& s, const std::string& problem);

}  // namespace ms
