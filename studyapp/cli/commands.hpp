// The `modalstudy` subcommands: each file registers one on the CLI11 app.
#pragma once
#include <CLI/CLI.hpp>

namespace ms::cli {

void register_synth(CLI::App& app);
void register_stimuli(CLI::App& app);
void register_bench(CLI::App& app);
void register_materials(CLI::App& app);
void register_fit_damping(CLI::App& app);
void register_validate_damping(CLI::App& app);
void register_extract(CLI::App& app);
void register_prune(CLI::App& app);
void register_stats(CLI::App& app);
void register_plot(CLI::App& app);
void register_export(CLI::App& app);
void register_protocol(CLI::App& app);
void register_audit(CLI::App& app);
void register_audit_generate(CLI::App& app);
void register_compare(CLI::App& app);
void register_estimate(CLI::App& app);
void register_serve(CLI::App& app);

}  // namespace ms::cli
