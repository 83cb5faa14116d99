// Fixtures of the core tests: a small protocol on disk (two one-mode parameter sets, a derived anchor
// and one block of each answered kind), and simulated participants run into a store and exported.
#pragma once
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "studyapp/core/autopilot.hpp"
#include "studyapp/core/export.hpp"
#include "studyapp/core/protocol_parser.hpp"
#include "studyapp/core/session.hpp"
#include "studyapp/core/stimulus_cache.hpp"
#include "support/test_util.hpp"

namespace ms::testing {

// A file's whole text (a protocol's, for a Session).
inline std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::string write_small_study(const test::TempDir& dir, const std::string& extra_blocks = "") {
  dir.write("sets/low.yaml",
            "sample_rate: 44100\nduration_s: 0.5\nmodes:\n  - {freq_hz: 440.0, decay_per_s: 6.0, amp: 0.5}\n"
            "  - {freq_hz: 5200.0, decay_per_s: 20.0, amp: 0.3}\nexcitation: {type: impulse}\n"
            "level: {normalize: none}\n");
  dir.write("sets/high.yaml",
            "sample_rate: 44100\nduration_s: 0.5\nmodes:\n  - {freq_hz: 880.0, decay_per_s: 6.0, amp: 0.5}\n"
            "excitation: {type: impulse}\nlevel: {normalize: none}\n");
  return dir.write("study.yaml",
                   "study: small\ntitle: Small\nsample_rate: 44100\nseed: 7\n"
                   "stimuli:\n"
                   "  low:  {paramset: sets/low.yaml}\n"
                   "  high: {paramset: sets/high.yaml}\n"
                   "  lowq: {paramset: sets/low.yaml, set: {amp_scale: 0.5}}\n"
                   "  lp:   {derive: low, lowpass_hz: 3500}\n"
                   "blocks:\n"
                   "  - {type: instructions, id: hello, text: Listen.}\n"
                   "  - {type: identify, id: id, stimuli: [low, high], labels: [low, high], repeats: 2}\n"
                   "  - {type: mushra, id: mu, reference: low, conditions: [lowq, lp]}\n" +
                       extra_blocks);
}

// The small study on disk with what opening a session on it takes: the protocol loaded, its text (the
// store keeps it and refuses a changed one) and its stimuli's hashes.
struct SmallStudy {
  explicit SmallStudy(const test::TempDir& dir, const std::string& extra_blocks = "")
      : path(write_small_study(dir, extra_blocks)), protocol(load_protocol(path)), text(file_text(path)),
        cache(protocol, "") {}

  // `participant`'s session in the store at `db`, opened at `now_ms`.
  Session open(const std::string& participant, const std::string& db, std::int64_t now_ms,
               const SessionStart& start = {}) {
    return Session(protocol, text, participant, db, cache.hashes(), now_ms, start);
  }

  std::string path;
  Protocol protocol;
  std::string text;
  StimulusCache cache;
};

// An answer the small study's current trial accepts: "ok", the first stimulus's label, or every
// MUSHRA condition at 50.
inline nlohmann::json good_answer(const Session& s) {
  const Trial& t = s.current();
  if (t.type == BlockType::instructions) return "ok";
  if (t.type == BlockType::identify) return t.stimuli.at(0);  // labels equal the stimulus names
  nlohmann::json v = nlohmann::json::object();
  for (const auto& name : t.stimuli) v[name] = 50;
  return v;
}

// Autopilot options for a shipped protocol (protocols/NAME), with the store and the cache in `dir`.
inline AutopilotOptions shipped_study(const std::string& protocol_name, const test::TempDir& dir) {
  AutopilotOptions o;
  o.protocol_path = std::string(MODALSTUDY_SOURCE_DIR) + "/protocols/" + protocol_name;
  o.db_path = dir.file("study.sqlite");
  o.cache_dir = dir.file("cache");
  return o;
}

// Runs `participants` simulated participants (codes prefix0, prefix1, ...; seeds first_seed,
// first_seed + 1, ...) with `o`'s protocol, store and cache, then exports the store into `out_dir`.
// False when a session did not finish.
inline bool run_participants_and_export(AutopilotOptions o, int participants, const std::string& prefix,
                                        std::uint64_t first_seed, const std::string& out_dir) {
  for (int p = 0; p < participants; ++p) {
    o.participant = prefix + std::to_string(p);
    o.seed = first_seed + std::uint64_t(p);
    if (!run_autopilot(o).finished) return false;
  }
  export_results(o.db_path, out_dir);
  return true;
}

}  // namespace ms::testing
