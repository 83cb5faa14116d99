// The `modalstudy plot` subcommands kept in their own files, each registered on the plot group.
#pragma once
#include <CLI/CLI.hpp>

namespace ms::cli {

void register_plot_demo(CLI::App& group);
void register_plot_lines(CLI::App& group);

}  // namespace ms::cli
