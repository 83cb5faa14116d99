// modalstudy plot lines DATA.csv --x X --y Y [--series S] -o FILE: the mean of a column against another
// from tidy data, one line per series.
#include <map>
#include <string>
#include <vector>
#include <iostream>

#include "synthesis/tidy_csv.hpp"
#include "studyapp/cli/plot_commands.hpp"
#include "studyapp/plots/plots.hpp"
#include "synthesis/input_error.hpp"

namespace ms::cli {

using plots::PlotOptions;

void register_plot_lines(CLI::App& group) {
  // Lines from tidy data, e.g. perceived difference vs number of modes, one line per method: the
  // mean of y at each x per series (several listeners' rows average).
  struct LineOptions {
    std::string data, x, y, series, output, title, x_label, y_label;
    bool log_x = false;
  };
  auto lo = std::make_shared<LineOptions>();
  CLI::App* lines_cmd = group.add_subcommand(
      "lines", "Mean of a column against another from tidy CSV, one line per series (e.g. difference vs modes)");
  lines_cmd->add_option("data", lo->data, "Tidy CSV")->required();
  lines_cmd->add_option("--x", lo->x, "Column on the x axis (numeric)")->required();
  lines_cmd->add_option("--y", lo->y, "Column averaged on the y axis (numeric)")->required();
  lines_cmd->add_option("--series", lo->series, "Column naming the lines (default: one line)");
  lines_cmd->add_option("-o,--output", lo->output, "Picture: .png or .svg")->required();
  lines_cmd->add_option("--title", lo->title, "Title (default: y vs x)");
  lines_cmd->add_option("--x-label", lo->x_label, "x-axis label with unit (default: the column)");
  lines_cmd->add_option("--y-label", lo->y_label, "y-axis label with unit (default: the column)");
  lines_cmd->add_flag("--log-x", lo->log_x, "Logarithmic x axis");
  lines_cmd->callback([lo] {
    plots::check_output_path(lo->output);
    const TidyCsv table = TidyCsv::read(lo->data);
    if (table.rows() == 0) throw InputError(SourceLocation{table.file(), 0, 0}, "no data rows");
    const std::size_t cx = table.column(lo->x), cy = table.column(lo->y);
    const bool by_series = !lo->series.empty();
    const std::size_t cs = by_series ? table.column(lo->series) : 0;
    std::vector<std::string> order;
    std::map<std::string, std::map<double, std::pair<double, int>>> sums;  // series -> x -> (sum y, n)
    for (std::size_t r = 0; r < table.rows(); ++r) {
      const std::string name = by_series ? table.cell(r, cs) : lo->y;
      if (!sums.count(name)) order.push_back(name);
      auto& cell = sums[name][table.number(r, cx)];
      cell.first += table.number(r, cy);
      cell.second += 1;
    }
    std::vector<plots::Series> series;
    for (const auto& name : order) {
      plots::Series s{name, {}};
      for (const auto& [x, acc] : sums[name]) s.points.push_back({x, acc.first / acc.second});
      series.push_back(std::move(s));
    }
    PlotOptions o;
    o.title = lo->title.empty() ? lo->y + " vs " + lo->x : lo->title;
    o.x_label = lo->x_label.empty() ? lo->x : lo->x_label;
    o.y_label = lo->y_label.empty() ? lo->y : lo->y_label;
    plots::line_plot(lo->output, series, o, lo->log_x);
    std::cout << "wrote " << lo->output << "\n";
  });
}

}  // namespace ms::cli
