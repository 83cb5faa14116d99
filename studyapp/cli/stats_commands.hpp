// The `modalstudy stats` subcommands: each cmd_stats_<name>.cpp registers one on the stats group.
#pragma once
#include <CLI/CLI.hpp>

namespace ms::cli {

void register_stats_anova(CLI::App& group);
void register_stats_ttest(CLI::App& group);
void register_stats_confusion(CLI::App& group);
void register_stats_mushra(CLI::App& group);
void register_stats_bs1116(CLI::App& group);
void register_stats_ab(CLI::App& group);
void register_stats_staircase(CLI::App& group);
void register_stats_limits(CLI::App& group);
void register_stats_tokens(CLI::App& group);
void register_stats_changepoint(CLI::App& group);
void register_stats_mds(CLI::App& group);
void register_stats_magnitude(CLI::App& group);
void register_stats_reference_error(CLI::App& group);
void register_stats_adjust(CLI::App& group);

}  // namespace ms::cli
