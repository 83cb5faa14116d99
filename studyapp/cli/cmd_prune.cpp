// modalstudy prune MODES.csv --method masking|naive|energy|loudness [--threshold-db A]
//   [--playback-db L] [--combine max|sum] [--order naive|energy|loudness] [--keep K] [-o OUT.csv] [--json]
// Masking-based mode pruning (synthesis/masking_pruning.hpp); writes a progressive model on request.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>

#include "synthesis/masking_pruning.hpp"
#include "studyapp/cli/commands.hpp"
#include "studyapp/cli/prune_csv.hpp"
#include "studyapp/cli/stats_output.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/modes_csv.hpp"

namespace ms::cli {

namespace {

constexpr const char* kDescription =
    "Prune inaudible modes by auditory masking (van den Doel, Pai et al. 2002) and order the rest for\n"
    "progressive synthesis.\n"
    "  power P = amp^2/decay; level L = playback + 10 log10(P / sum P) dB;\n"
    "  Bark z = 13 atan(0.00076 f) + 3.5 atan((f/7500)^2);\n"
    "  masking of m by n: L_n - a_v - 25 (z_n - z_m) if z_m <= z_n,\n"
    "                     L_n - a_v - max(0, 22 - L_n/5) (z_m - z_n) otherwise;\n"
    "  m is inaudible below the max (--combine max) or power sum (--combine sum) of the masking by\n"
    "  all other modes, or below Terhardt's threshold in quiet.\n"
    "Methods: 'masking' keeps the audible modes, ordered by --order (default energy). 'naive',\n"
    "'energy' and 'loudness' apply no masking: they keep ALL modes, ordered by amp, by amp^2/decay,\n"
    "or by dB above the masking threshold (the 2002 study's progressive-synthesis baselines).\n"
    "Ties are ordered by row index. --json prints {kept, dropped, levels_db, ...} with 0-based data-row\n"
    "indices; a level or threshold of minus infinity (amp 0, or no masker) is written as null.\n"
    "A mode with decay_per_s 0 has infinite power and is rejected.";

template <class T>
T parse_choice(std::optional<T> parsed, const std::string& text, const std::string& option,
               const char* choices) {
  if (!parsed) throw InputError(option + ": expected one of " + choices + ", got '" + text + "'");
  return *parsed;
}

nlohmann::json db_array(const std::vector<double>& v) {
  nlohmann::json a = nlohmann::json::array();
  for (double x : v) a.push_back(num_json(x));
  return a;
}

}  // namespace

void register_prune(CLI::App& app) {
  struct Options {
    std::string modes, method, threshold_db, playback_db, combine, order, keep, output;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("prune", kDescription);
  cmd->add_option("modes", opt->modes, "Modes CSV (freq_hz,decay_per_s,amp)")->required();
  cmd->add_option("--method", opt->method, "masking | naive | energy | loudness (required)")
      ->type_name("METHOD");
  cmd->add_option("--threshold-db", opt->threshold_db,
                  "Masking threshold a_v [dB], in [-20, 60]; default 16 (the study's median)")
      ->type_name("A");
  cmd->add_option("--playback-db", opt->playback_db,
                  "Playback level of the whole model right after the impact [dB SPL], in [0, 130]; "
                  "default 70")
      ->type_name("L");
  cmd->add_option("--combine", opt->combine, "How maskings combine: max (upper envelope, default) | sum (power)")
      ->type_name("HOW");
  cmd->add_option("--order", opt->order,
                  "Order of the survivors for --method masking: naive | energy (default) | loudness")
      ->type_name("ORDER");
  cmd->add_option("--keep", opt->keep, "Write only the first K kept modes (needs -o); K >= 1")
      ->type_name("K");
  cmd->add_option("-o,--output", opt->output, "Write the kept modes, in order, as a modes CSV");
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  cmd->callback([opt] {
    // Options first (nothing read or written yet), each error naming the modes file and the option.
    auto option_error = [&](const std::string& problem) {
      return InputError(SourceLocation{opt->modes, 0, 0}, problem);
    };
    if (opt->method.empty())
      throw option_error("--method is required: masking | naive | energy | loudness");
    PruneOptions o;
    try {
      o.method = parse_choice(parse_prune_method(opt->method), opt->method, "--method",
                              "masking|naive|energy|loudness");
      if (!opt->combine.empty())
        o.combine = parse_choice(parse_masking_combine(opt->combine), opt->combine, "--combine", "max|sum");
      if (!opt->order.empty())
        o.order = parse_choice(parse_mode_order(opt->order), opt->order, "--order",
                               "naive|energy|loudness");
      if (!opt->threshold_db.empty()) o.threshold_db = parse_number(opt->threshold_db, "--threshold-db");
      if (!opt->playback_db.empty()) o.playback_db = parse_number(opt->playback_db, "--playback-db");
    } catch (const InputError& e) {
      throw option_error(e.problem());
    }
    if (!opt->order.empty() && o.method != PruneMethod::masking)
      throw option_error("--order applies to --method masking only (--method " + opt->method +
                         " orders by itself)");
    try {
      validate_prune_options(o);
    } catch (const PruneError& e) {
      std::string option = "--" + e.field();
      std::replace(option.begin(), option.end(), '_', '-');
      throw option_error(option + " " + e.problem());
    }
    std::size_t keep = 0;
    if (!opt->keep.empty()) {
      unsigned long long k = 0;
      auto [ptr, ec] = std::from_chars(opt->keep.data(), opt->keep.data() + opt->keep.size(), k);
      if (opt->keep.empty() || opt->keep[0] == '-' || ec != std::errc() ||
          ptr != opt->keep.data() + opt->keep.size() || k == 0)
        throw option_error("--keep: expected a whole number >= 1, got '" + opt->keep + "'");
      if (opt->output.empty()) throw option_error("--keep needs -o OUT.csv to write the kept modes to");
      keep = std::size_t(k);
    }

    const auto [model, r] = prune_modes_csv(opt->modes, o);

    std::size_t written = 0;
    if (!opt->output.empty()) {
      const ModalModel out = progressive_model(model, r, keep == 0 ? r.kept.size() : keep);
      write_modes_csv(opt->output, out);
      written = out.modes.size();
    }

    if (opt->json) {
      nlohmann::json j = {{"input", opt->modes},
                          {"modes", model.modes.size()},
                          {"method", to_string(o.method)},
                          {"order", to_string(effective_order(o))},
                          {"combine", to_string(o.combine)},
                          {"threshold_db", o.threshold_db},
                          {"playback_db", o.playback_db},
                          {"kept", r.kept},
                          {"dropped", r.dropped},
                          {"levels_db", db_array(r.level_db)},
                          {"masking_threshold_db", db_array(r.masking_db)},
                          {"threshold_in_quiet_db", db_array(r.quiet_db)},
                          {"loudness_db", db_array(r.loudness_db)},
                          {"bark", r.bark},
                          {"audible", r.audible}};
      if (!opt->output.empty()) {
        j["output"] = opt->output;
        j["written"] = written;
      }
      std::cout << j.dump() << "\n";
      return;
    }
    std::printf("%s: %zu of %zu modes kept (method %s", opt->modes.c_str(), r.kept.size(),
                model.modes.size(), std::string(to_string(o.method)).c_str());
    if (o.method == PruneMethod::masking)
      std::printf(", order %s, a_v %g dB, playback %g dB SPL, combine %s",
                  std::string(to_string(o.order)).c_str(), o.threshold_db, o.playback_db,
                  std::string(to_string(o.combine)).c_str());
    std::printf(")\n%5s %5s %12s %12s %12s %9s %9s %9s\n", "rank", "row", "freq_hz", "decay_per_s",
                "amp", "level_db", "thresh_db", "above_db");
    for (std::size_t i = 0; i < r.kept.size(); ++i) {
      const std::size_t n = r.kept[i];
      const Mode& m = model.modes[n];
      std::printf("%5zu %5zu %12.6g %12.6g %12.6g %9.2f %9.2f %9.2f\n", i + 1, n, m.freq_hz,
                  m.decay_per_s, m.amp, r.level_db[n], std::max(r.masking_db[n], r.quiet_db[n]),
                  r.loudness_db[n]);
    }
    if (!opt->output.empty())
      std::printf("wrote %zu modes to %s%s\n", written, opt->output.c_str(),
                  keep > written ? " (fewer than --keep: that is all that were kept)" : "");
  });
}

}  // namespace ms::cli
