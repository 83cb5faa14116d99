// Who may take part through `serve`: participant ids and the token of each one's link. Either issued
// (N participants web-001.., fresh tokens) or read from a CSV the experimenter provides
// (`participant,token` with a header; tokens of 32..128 hex digits). Issued links are written to a
// links file (mode 0600) so that a restarted server gives the same links again.
#pragma once
#include <string>
#include <vector>

namespace ms::web {

struct ParticipantLink {
  std::string participant;  // as stored (normalised)
  std::string token;
};

// Reads `participant,token` rows. Throws InputError at file:line:column for a missing column, a token
// that is not 32..128 hex digits, or a participant or token that appears twice.
std::vector<ParticipantLink> read_participant_list(const std::string& path);

// `count` participants web-001, web-002, ... with fresh tokens.
std::vector<ParticipantLink> issue_participants(std::size_t count);

// Writes the links as a participant list (readable by read_participant_list), atomically, mode 0600.
void write_participant_list(const std::string& path, const std::vector<ParticipantLink>& links);

}  // namespace ms::web
