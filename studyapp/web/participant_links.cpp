// Participant lists: the one CSV reader and writer, tokens checked for their shape and uniqueness.
#include "studyapp/web/participant_links.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <set>

#include "studyapp/core/participant_id.hpp"
#include "studyapp/web/web_token.hpp"
#include "synthesis/atomic_file.hpp"
#include "synthesis/csv.hpp"
#include "synthesis/input_error.hpp"

namespace ms::web {

std::vector<ParticipantLink> read_participant_list(const std::string& path) {
  const std::vector<csv::Record> records = csv::parse(csv::read_file(path), path);
  if (records.empty()) throw InputError(SourceLocation{path, 1, 1}, "empty participant list (expected a header participant,token)");
  const csv::Record& header = records.front();
  if (header.cells.size() != 2 || header.cells[0] != "participant" || header.cells[1] != "token")
    throw InputError(header.where.front(), "the header must be participant,token");
  std::vector<ParticipantLink> links;
  std::set<std::string> participants, tokens;
  for (std::size_t r = 1; r < records.size(); ++r) {
    const csv::Record& row = records[r];
    if (row.cells.size() != 2) throw InputError(row.where.front(), "expected 2 cells (participant,token), found " + std::to_string(row.cells.size()));
    ParticipantLink link{normalize_participant_id(row.cells[0]), row.cells[1]};
    if (link.participant.empty()) throw InputError(row.where[0], "empty participant id");
    if (!token_shaped(link.token))
      throw InputError(row.where[1], "a token must be 32 to 128 hex digits (0-9, a-f): 128 bits or more");
    if (!participants.insert(participant_id_key(link.participant)).second)
      throw InputError(row.where[0], "participant '" + link.participant + "' is listed twice");
    if (!tokens.insert(link.token).second) throw InputError(row.where[1], "this token is listed twice");
    links.push_back(std::move(link));
  }
  if (links.empty()) throw InputError(SourceLocation{path, 2, 1}, "no participants listed");
  return links;
}

std::vector<ParticipantLink> issue_participants(std::size_t count) {
  std::vector<ParticipantLink> links;
  for (std::size_t i = 1; i <= count; ++i) {
    char id[32];
    std::snprintf(id, sizeof id, "web-%03zu", i);
    links.push_back({id, new_token()});
  }
  return links;
}

void write_participant_list(const std::string& path, const std::vector<ParticipantLink>& links) {
  std::string text = csv::line({"participant", "token"});
  for (const ParticipantLink& l : links) text += csv::line({l.participant, l.token});
  write_atomically(path, [&](const std::string& temp) {
    // The tokens are keys: only the experimenter may read the file (0600 from its creation on).
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    if (fd < 0) throw InputError(SourceLocation{path, 0, 0}, "cannot write the participant list");
    const bool written = ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
    const bool closed = ::close(fd) == 0;
    if (!written || !closed) throw InputError(SourceLocation{path, 0, 0}, "cannot write the participant list");
  });
}

}  // namespace ms::web
