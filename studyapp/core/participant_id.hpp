// Participant ids as people type them: surrounding spaces are not part of an id, an empty id or one
// with control characters is refused, and ids that differ only by case or inner spaces ("P07",
// "p07", "P 07") are reported as look-alikes so a typo does not silently create a new participant.
#pragma once
#include <string>
#include <vector>

namespace ms {

// Trims ASCII white space; throws InputError ("the participant id ...") for an empty id, one with
// control characters, or one longer than 200 bytes.
std::string normalize_participant_id(const std::string& typed);

// The key look-alikes share: lower case, with every white space removed.
std::string participant_id_key(const std::string& id);

// Those of `existing` that are look-alikes of `id` but not equal to it.
std::vector<std::string> look_alike_ids(const std::string& id, const std::vector<std::string>& existing);

}  // namespace ms
