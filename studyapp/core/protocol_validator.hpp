// Semantic checks of a parsed protocol that report EVERY problem (one line each, file:line:column):
// unknown block types, missing or cyclic stimuli, paths escaping the allowed folders, missing files,
// duplicate ids, empty blocks, MUSHRA without reference, identify without labels.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "studyapp/core/protocol.hpp"
#include "synthesis/path_confinement.hpp"

namespace ms {

struct ValidateOptions {
  bool allow_outside = false;      // also set by the protocol's top-level `allow_outside: true`
  std::string stimuli_dir;         // project stimuli/ folder; "" = <protocol dir>/stimuli or ../stimuli
  bool load_paramsets = true;      // load each named parameter set (surfacing its own errors)
};

std::vector<std::string> validate_protocol(const Protocol& p, const ValidateOptions& options = {});

// The folders every file the protocol reaches must lie in (its stimuli, their parameter sets' modes
// CSVs): its own folder and the project's stimuli/, or anywhere with allow_outside.
Confinement protocol_confinement(const Protocol& p, const ValidateOptions& options = {});

// Parse (collecting per-item problems) and validate a protocol file. `protocol` is empty only when
// the file could not be read or parsed at all (the reason is then the only problem).
// With options.allow_outside, the returned protocol's allow_outside is set too (the stimulus cache
// then reads what was checked).
struct ProtocolCheck {
  std::optional<Protocol> protocol;
  std::vector<std::string> problems;
  std::vector<std::string> warnings;  // legal but probably unintended (protocol_warnings)
};

// Legal constructs that are probably mistakes, one line each (file:line:column): a stimulus equal to
// an automatic MUSHRA anchor (`anchors: auto` already plays the 3.5 and 7 kHz low-passes, so the
// listener would rate the same sound twice).
std::vector<std::string> protocol_warnings(const Protocol& p);
ProtocolCheck check_protocol_file(const std::string& path, const ValidateOptions& options = {});

}  // namespace ms
