// What every `modalstudy stats` subcommand does to the table it reads before its statistic: keep the
// rows --where COL=VALUE selects, drop autopilot sessions with --exclude-autopilot, and warn (one
// line on stderr) when a participant answered in more than one session.
#pragma once
#include <CLI/CLI.hpp>

#include <cctype>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "synthesis/tidy_csv.hpp"
#include "synthesis/input_error.hpp"

namespace ms::cli {

struct StatsInput {
  bool exclude_autopilot = false;
  std::vector<std::string> where;  // COL=VALUE, all must hold
};

inline void add_input_options(CLI::App* cmd, StatsInput& in) {
  cmd->add_flag("--exclude-autopilot", in.exclude_autopilot,
                "Drop the rows of simulated-listener sessions (column 'autopilot' = 1 or true)");
  cmd->add_option("--where", in.where, "Keep only rows where column COL equals VALUE: COL=VALUE (repeatable)");
}

// True/false from 1/0, true/false, yes/no (any case); InputError at the cell otherwise.
inline bool table_flag(const TidyCsv& t, std::size_t row, std::size_t col) {
  std::string v = t.cell(row, col);
  for (char& c : v) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (v == "1" || v == "true" || v == "yes") return true;
  if (v == "0" || v == "false" || v == "no") return false;
  throw InputError(t.where(row, col), "column '" + t.header()[col] + "': expected 1/0 or true/false, got '" +
                                          t.cell(row, col) + "'");
}

// One line naming the participants with more than one session, or "" (needs columns participant, session).
inline std::string several_sessions_warning(const TidyCsv& t) {
  if (!t.has_column("participant") || !t.has_column("session")) return "";
  const std::size_t cp = t.column("participant"), cs = t.column("session");
  std::map<std::string, std::set<std::string>> sessions;
  for (std::size_t r = 0; r < t.rows(); ++r) sessions[t.cell(r, cp)].insert(t.cell(r, cs));
  std::string list;
  std::size_t several = 0;
  for (const auto& [who, s] : sessions) {
    if (s.size() < 2) continue;
    ++several;
    if (several > 5) continue;
    std::string ids;
    for (const auto& id : s) ids += (ids.empty() ? "" : ", ") + id;
    list += std::string(list.empty() ? "" : "; ") + who + ": sessions " + ids;
  }
  if (several == 0) return "";
  if (several > 5) list += "; ...";
  return std::to_string(several) + " participant(s) answered in more than one session (" + list +
         "); all their rows are used (select one with --where session=N)";
}

// Reads `path`, applies the filters and prints the several-sessions warning on stderr.
inline TidyCsv read_stats_table(const std::string& path, const StatsInput& in) {
  TidyCsv t = TidyCsv::read(path);
  std::vector<std::pair<std::size_t, std::string>> conditions;
  for (const std::string& w : in.where) {
    const auto eq = w.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError(SourceLocation{"--where", 0, 0}, "expected COL=VALUE, got '" + w + "'");
    conditions.emplace_back(t.column(w.substr(0, eq)), w.substr(eq + 1));
  }
  std::size_t col_autopilot = 0;
  if (in.exclude_autopilot) {
    if (!t.has_column("autopilot"))
      throw InputError(SourceLocation{path, 1, 1}, "--exclude-autopilot: the table has no column 'autopilot' (export "
                                                   "the results again with `modalstudy export`)");
    col_autopilot = t.column("autopilot");
  }
  if (conditions.empty() && !in.exclude_autopilot) {
    if (const std::string w = several_sessions_warning(t); !w.empty()) std::cerr << "warning: " << path << ": " << w << "\n";
    return t;
  }
  std::vector<std::size_t> keep;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    bool ok = !in.exclude_autopilot || !table_flag(t, r, col_autopilot);
    for (const auto& [c, value] : conditions) ok = ok && t.cell(r, c) == value;
    if (ok) keep.push_back(r);
  }
  if (keep.empty() && t.rows() > 0)
    throw InputError(SourceLocation{path, 0, 0}, "no rows left after " +
                                                     std::string(in.exclude_autopilot ? "--exclude-autopilot" : "") +
                                                     (in.exclude_autopilot && !conditions.empty() ? " and " : "") +
                                                     (conditions.empty() ? "" : "--where"));
  t = t.keep_rows(keep);
  if (const std::string w = several_sessions_warning(t); !w.empty()) std::cerr << "warning: " << path << ": " << w << "\n";
  return t;
}

}  // namespace ms::cli
