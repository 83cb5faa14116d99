// Reading protocols/*.yaml into a Protocol with the strict YamlReader: unknown keys (nearest key
// suggested), types and ranges are InputErrors naming file:line:column.
#pragma once
#include <string>
#include <vector>

#include "studyapp/core/protocol.hpp"

namespace ms {

// Parses a protocol. With `problems` given, a bad stimulus or block is reported there (one line,
// file:line:column) and skipped so that reading continues; without it the first problem throws.
// YAML syntax errors and a malformed top level always throw. Unknown block types are not parse
// errors: they are kept as BlockType::unknown for the validator (which suggests the nearest type).
Protocol parse_protocol(const std::string& yaml_text, const std::string& file_for_errors,
                        const std::string& base_dir, std::vector<std::string>* problems = nullptr);
Protocol load_protocol(const std::string& path, std::vector<std::string>* problems = nullptr);

}  // namespace ms
