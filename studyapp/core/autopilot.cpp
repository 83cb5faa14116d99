// run_autopilot: protocol check, stimulus cache, session, simulated listener, in that order.
#include "studyapp/core/autopilot.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "studyapp/core/protocol_validator.hpp"
#include "studyapp/core/session.hpp"
#include "studyapp/core/simulated_listener.hpp"
#include "studyapp/core/stimulus_cache.hpp"
#include "studyapp/core/store_location.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/yaml_reader.hpp"

namespace ms {

namespace fs = std::filesystem;

InvalidProtocol::InvalidProtocol(std::vector<std::string> problems)
    : InputError(problems.empty() ? std::string("invalid protocol")
                                  : problems.front() + (problems.size() > 1 ? " (and " + std::to_string(problems.size() - 1) +
                                                                                  " more problems)"
                                                                            : std::string())),
      problems_(std::move(problems)) {}

std::string default_db_path(const std::string& protocol_path, const std::string& study) {
  // The id becomes a file name: "../../x" must not leave results/.
  if (!is_identifier(study))
    throw InputError(SourceLocation{protocol_path, 0, 0}, "study id '" + study + "' cannot name a database file");
  return (fs::path(protocol_path).parent_path() / "results" / (study + ".sqlite")).lexically_normal().string();
}

AutopilotSummary run_autopilot(const AutopilotOptions& o, const std::function<void(const std::string&)>& log) {
  ValidateOptions vo;
  vo.allow_outside = o.allow_outside;
  const ProtocolCheck check = check_protocol_file(o.protocol_path, vo);
  if (!check.problems.empty()) throw InvalidProtocol(check.problems);
  const Protocol& protocol = *check.protocol;
  std::ifstream in(o.protocol_path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();

  StimulusCache cache(protocol, o.cache_dir);
  cache.prepare_all([&](std::size_t done, std::size_t total, const std::string& name) {
    if (log) log("rendered " + std::to_string(done) + "/" + std::to_string(total) + " " + name);
  });
  AutopilotSummary summary;
  summary.db_path = o.db_path.empty() ? default_db_path(o.protocol_path, protocol.study) : o.db_path;
  if (const auto dir = fs::path(summary.db_path).parent_path(); !dir.empty() && !is_postgres_uri(summary.db_path))
    fs::create_directories(dir);
  Session session(protocol, text.str(), o.participant, summary.db_path, cache.hashes(), unix_now_ms(),
                  SessionStart{o.new_session, true});
  summary.warnings = session.warnings();
  summary.session = session.id();
  summary.resumed = session.resumed();
  summary.total = session.total();
  SimulatedListener listener(cache, o.seed ^ std::hash<std::string>{}(session.participant()));
  while (!session.finished() && (o.stop_after == 0 || summary.answered_now < o.stop_after)) {
    const Trial trial = session.current();
    const Block& block = session.current_block();
    if (const auto* s = std::get_if<StaircaseBlock>(&block.body)) {
      const AbInterval chosen = listener.staircase_choice(*s, session.staircase().level(), session.staircase_comparison());
      const std::size_t before = session.current_index();
      session.log_event(EventKind::play, trial.stimuli.back(), unix_now_ms());
      session.staircase_step(chosen, 1200.0, unix_now_ms());
      if (session.current_index() != before) {  // the track finished: the trial is answered
        ++summary.answered_now;
        if (log) log("answered " + trial.block_id + " (staircase track)");
      }
      continue;
    }
    if (const auto* l = std::get_if<LimitsBlock>(&block.body)) {
      const bool different = listener.limits_different(*l, session.limits().level());
      for (const auto& name : trial.stimuli) session.log_event(EventKind::play, name, unix_now_ms());
      if (!session.limits_step(different, 1500.0, unix_now_ms())) {  // the series ended: the trial is answered
        ++summary.answered_now;
        if (log) log("answered " + trial.block_id + " (descending series)");
      }
      continue;
    }
    if (const auto* t = std::get_if<TokensBlock>(&block.body)) {
      TokenSeries& series = session.tokens();
      const bool different = listener.tokens_different(*t, series.reference(), series.comparison());
      session.log_event(EventKind::play, trial.stimuli.front(), unix_now_ms());
      if (!session.tokens_step(different, 1500.0, unix_now_ms())) {  // the last token compared: the trial is answered
        ++summary.answered_now;
        if (log) log("answered " + trial.block_id + " (token series)");
      }
      continue;
    }
    const SimulatedAnswer a = listener.answer(block, trial);
    for (const auto& name : trial.stimuli) session.log_event(EventKind::play, name, unix_now_ms());
    const nlohmann::json value = a.value;
    session.answer(value, a.rt_ms, a.plays, unix_now_ms());
    ++summary.answered_now;
    if (log) log("answered " + trial.block_id + " trial " + std::to_string(trial.index) + ": " + value.dump());
  }
  summary.finished = session.finished();
  return summary;
}

}  // namespace ms
