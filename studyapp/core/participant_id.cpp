// Participant id normalisation and look-alikes; see participant_id.hpp.
#include "studyapp/core/participant_id.hpp"

#include <algorithm>
#include <cctype>

#include "synthesis/input_error.hpp"

namespace ms {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }

}  // namespace

std::string normalize_participant_id(const std::string& typed) {
  std::size_t first = 0, last = typed.size();
  while (first < last && is_space(typed[first])) ++first;
  while (last > first && is_space(typed[last - 1])) --last;
  const std::string id = typed.substr(first, last - first);
  if (id.empty()) throw InputError("the participant id is empty");
  if (id.size() > 200) throw InputError("the participant id is longer than 200 characters");
  if (std::any_of(id.begin(), id.end(), [](char c) { return (unsigned char)c < 0x20 || c == 0x7f; }))
    throw InputError("the participant id '" + id + "' contains a control character");
  return id;
}

std::string participant_id_key(const std::string& id) {
  std::string key;
  for (char c : id)
    if (!is_space(c)) key += char(std::tolower((unsigned char)c));
  return key;
}

std::vector<std::string> look_alike_ids(const std::string& id, const std::vector<std::string>& existing) {
  const std::string key = participant_id_key(id);
  std::vector<std::string> out;
  for (const auto& e : existing)
    if (e != id && participant_id_key(e) == key) out.push_back(e);
  return out;
}

}  // namespace ms
