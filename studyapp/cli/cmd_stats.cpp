// modalstudy stats anova|ttest|confusion|mushra|bs1116|ab|staircase|limits|tokens|changepoint|mds|magnitude ...: statistics of
// perceptual studies from tidy CSV files (one row per response). Each prints a table, or one JSON
// object with --json; each subcommand is in its own cmd_stats_<name>.cpp.
#include "studyapp/cli/commands.hpp"
#include "studyapp/cli/stats_commands.hpp"

namespace ms::cli {

void register_stats(CLI::App& app) {
  CLI::App* group = app.add_subcommand("stats", "Statistics of perceptual studies from tidy CSV files");
  group->require_subcommand(1);
  register_stats_anova(*group);
  register_stats_ttest(*group);
  register_stats_confusion(*group);
  register_stats_mushra(*group);
  register_stats_bs1116(*group);
  register_stats_ab(*group);
  register_stats_staircase(*group);
  register_stats_limits(*group);
  register_stats_tokens(*group);
  register_stats_changepoint(*group);
  register_stats_mds(*group);
  register_stats_magnitude(*group);
  register_stats_reference_error(*group);
  register_stats_adjust(*group);
}

}  // namespace ms::cli
