// modalstudy stats mds: multidimensional scaling (analysis/mds.hpp, mds_cityblock.hpp) of a
// dissimilarity matrix, square or long form.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstdio>
#include <iostream>

#include "analysis/stats/dissimilarity_matrix.hpp"
#include "analysis/stats/mds.hpp"
#include "analysis/stats/mds_cityblock.hpp"
#include "studyapp/cli/stats_commands.hpp"
#include "studyapp/cli/stats_input.hpp"
#include "studyapp/cli/stats_output.hpp"
#include "studyapp/plots/plots.hpp"
#include "synthesis/atomic_file.hpp"
#include "synthesis/csv.hpp"

namespace ms::cli {

void register_stats_mds(CLI::App& group) {
  struct Options {
    std::string data, method = "classical", output, plot;
    std::vector<std::string> pairs;
    int dims = 2, starts = 3;
    std::uint64_t seed = 1;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = group.add_subcommand("mds", "Multidimensional scaling of dissimilarities: classical, SMACOF, nonmetric");
  auto in = std::make_shared<StatsInput>();
  add_input_options(cmd, *in);
  cmd->add_option("data", opt->data, "Square dissimilarity matrix CSV (label column + one column per stimulus)")
      ->required();
  cmd->add_option("--dims", opt->dims, "Dimensions of the map")->check(CLI::Range(1, 10))->capture_default_str();
  cmd->add_option("--method", opt->method, "classical | smacof | nonmetric | cityblock (metric SMACOF, L1 distances)")
      ->check(CLI::IsMember({"classical", "smacof", "nonmetric", "cityblock"}))
      ->capture_default_str();
  cmd->add_option("--pairs", opt->pairs, "Read long form instead: FIRST,SECOND,VALUE columns (ratings averaged)");
  cmd->add_option("--starts", opt->starts, "Random starts besides the classical one (smacof, nonmetric)")
      ->check(CLI::Range(0, 1000));
  cmd->add_option("--seed", opt->seed, "Seed of the random starts")->capture_default_str();
  cmd->add_option("-o,--output", opt->output, "Write the configuration as CSV (label, dim1, ...)");
  cmd->add_option("--plot", opt->plot, "Also draw the map (first two dimensions): FILE.png or FILE.svg");
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  cmd->callback([opt, in] {
    if (!opt->plot.empty()) {
      plots::check_output_path(opt->plot);
      if (opt->dims < 2) throw InputError(SourceLocation{"--plot", 0, 0}, "a map needs --dims 2 or more");
    }
    const TidyCsv table = read_stats_table(opt->data, *in);
    const std::vector<std::string> pairs = split_commas(opt->pairs);
    if (!opt->pairs.empty() && pairs.size() != 3)
      throw InputError(SourceLocation{}, "--pairs: give three columns FIRST,SECOND,VALUE");
    const DissimilarityMatrix d =
        pairs.empty() ? dissimilarity_from_square(table) : dissimilarity_from_pairs(table, pairs[0], pairs[1], pairs[2]);
    if (std::size_t(opt->dims) >= d.labels.size())
      throw InputError(SourceLocation{}, "--dims " + std::to_string(opt->dims) + ": need fewer dimensions than the " +
                                             std::to_string(d.labels.size()) + " stimuli");
    std::vector<std::string> notices;
    if (d.averaged_pairs)
      notices.push_back(std::to_string(d.averaged_pairs) + " pairs were rated more than once; ratings averaged");
    Eigen::MatrixXd points;
    nlohmann::json extra;
    if (opt->method == "classical") {
      const ClassicalMds c = classical_mds(d.values, opt->dims);
      points = c.points;
      std::vector<double> eig(c.eigenvalues.data(), c.eigenvalues.data() + c.eigenvalues.size());
      extra = {{"eigenvalues", eig}, {"stress1", stress1(d.values, points)}};
    } else {
      SmacofOptions o;
      o.dims = opt->dims;
      o.random_starts = opt->starts;
      o.seed = opt->seed;
      const SmacofResult r = opt->method == "smacof"      ? smacof(d.values, o)
                             : opt->method == "cityblock" ? smacof_cityblock(d.values, o)
                                                          : smacof_nonmetric(d.values, o);
      points = r.points;
      extra = {{"stress1", r.stress1}, {"raw_stress", r.raw_stress}, {"iterations", r.iterations},
               {"best_start", r.best_start}, {"starts", opt->starts + 1}, {"seed", opt->seed}};
    }
    if (!opt->output.empty()) {
      std::vector<std::string> header{"label"};
      for (int k = 0; k < opt->dims; ++k) header.push_back("dim" + std::to_string(k + 1));
      std::string csv = csv::line(header);
      for (std::size_t i = 0; i < d.labels.size(); ++i) {
        std::vector<std::string> cells{d.labels[i]};
        for (int k = 0; k < opt->dims; ++k) cells.push_back(fmt("%.17g", points(Eigen::Index(i), k)));
        csv += csv::line(cells);
      }
      write_file_atomically(opt->output, csv);
    }
    if (!opt->plot.empty()) {
      std::vector<plots::XY> xy;
      for (Eigen::Index i = 0; i < points.rows(); ++i) xy.push_back({points(i, 0), points(i, 1)});
      plots::PlotOptions po;
      po.title = "MDS (" + opt->method + "): " + opt->data + ", stress-1 " + fmt("%.3f", extra["stress1"].get<double>());
      po.x_label = "Dimension 1";
      po.y_label = "Dimension 2";
      plots::mds_map(opt->plot, xy, d.labels, po);
    }
    print_notices(notices, opt->data);
    if (opt->json) {
      nlohmann::json j = {{"method", opt->method}, {"dims", opt->dims}, {"labels", d.labels},
                          {"points", matrix_json(points)}, {"notices", notices}};
      j.update(extra);
      std::cout << j.dump() << "\n";
      return;
    }
    std::printf("%s MDS of %zu stimuli in %d dimensions: stress-1 = %.4f\n", opt->method.c_str(), d.labels.size(),
                opt->dims, extra["stress1"].get<double>());
    for (std::size_t i = 0; i < d.labels.size(); ++i) {
      std::printf("%-20s", d.labels[i].c_str());
      for (int k = 0; k < opt->dims; ++k) std::printf(" %10.4f", points(Eigen::Index(i), k));
      std::printf("\n");
    }
  });
}

}  // namespace ms::cli
