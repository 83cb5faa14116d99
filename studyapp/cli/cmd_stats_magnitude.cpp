// modalstudy stats magnitude: magnitude estimation of dissimilarity (analysis/magnitude_estimation.hpp)
// and its metric SMACOF map; with --vs REF, the difference to one reference token per token instead
// (van den Doel et al. 2002, Fig. 4: analysis/difference_curve.hpp).
#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstdio>
#include <iostream>
#include <optional>

#include "analysis/stats/difference_curve.hpp"
#include "analysis/stats/magnitude_estimation.hpp"
#include "analysis/stats/mds.hpp"
#include "studyapp/cli/stats_commands.hpp"
#include "studyapp/cli/stats_input.hpp"
#include "studyapp/cli/stats_output.hpp"
#include "synthesis/atomic_file.hpp"
#include "synthesis/csv.hpp"

namespace ms::cli {

namespace {

// Fig. 4: per token the mean (over listeners) difference to the reference; -o writes the curve.
void print_difference_curve(const std::vector<DifferencePoint>& curve, const std::string& reference, double offset,
                            const std::string& x, const std::string& output, bool json) {
  if (!output.empty()) {
    std::string csv = csv::line({x.empty() ? "x" : x, "token", "listeners", "difference", "sd"});
    for (const auto& p : curve)
      csv += csv::line({p.x.empty() ? "NA" : p.x, p.token, std::to_string(p.listeners), fmt("%.17g", p.mean), fmt("%.17g", p.sd)});
    write_file_atomically(output, csv);
  }
  if (json) {
    nlohmann::json points = nlohmann::json::array();
    for (const auto& p : curve)
      points.push_back({{"token", p.token}, {"x", p.x.empty() ? nlohmann::json() : nlohmann::json(p.x)},
                        {"listeners", p.listeners}, {"difference", num_json(p.mean)}, {"sd", num_json(p.sd)}});
    std::cout << nlohmann::json{{"reference", reference}, {"offset", offset}, {"points", points}}.dump() << "\n";
    return;
  }
  std::printf("difference to '%s' (each listener's mean rating of the pair, offset %+g, then the mean over listeners)\n",
              reference.c_str(), offset);
  std::printf("%-10s %-20s %9s %10s %8s\n", x.empty() ? "x" : x.c_str(), "token", "listeners", "difference", "sd");
  for (const auto& p : curve)
    std::printf("%-10s %-20s %9zu %10.3f %8s\n", p.x.empty() ? "-" : p.x.c_str(), p.token.c_str(), p.listeners, p.mean,
                fmt("%.3f", p.sd).c_str());
}

}  // namespace

// The modulus pair and value: the options when given, else the export's modulus columns (one pair
// and one value for all rows used); modulus_a/modulus_b are set to the pair used.
MagnitudeOptions magnitude_options(const TidyCsv& table, std::string& modulus_a, std::string& modulus_b,
                                   double modulus_value) {
  auto constant_column = [&](const std::string& name) -> std::optional<std::string> {
    if (!table.has_column(name) || table.rows() == 0) return std::nullopt;
    const std::size_t c = table.column(name);
    for (std::size_t r = 1; r < table.rows(); ++r)
      if (table.cell(r, c) != table.cell(0, c))
        throw InputError(table.where(r, c), "column '" + name + "': '" + table.cell(r, c) + "' here but '" +
                                                table.cell(0, c) + "' on line " + std::to_string(table.where(0, c).line) +
                                                ": rows from blocks with different moduli (choose one with --where block=ID)");
    return table.cell(0, c);
  };
  if (modulus_a.empty()) {
    const auto a = constant_column("modulus_a"), b = constant_column("modulus_b");
    if (a && b && !a->empty() && !b->empty()) {
      modulus_a = *a;
      modulus_b = *b;
    }
  }
  MagnitudeOptions mo;
  if (!modulus_a.empty()) mo.modulus = {modulus_a, modulus_b};
  if (modulus_value > 0) {
    mo.modulus_value = modulus_value;
  } else if (const auto v = constant_column("modulus_value"); v && !v->empty()) {
    mo.modulus_value = table.number(0, table.column("modulus_value"));
    if (!(mo.modulus_value > 0))
      throw InputError(table.where(0, table.column("modulus_value")), "column 'modulus_value': must be above 0");
  }
  return mo;
}

void register_stats_magnitude(CLI::App& group) {
  struct Options {
    std::string data, subject = "subject", first = "a", second = "b", rating = "rating", modulus_a, modulus_b, output;
    double modulus_value = 0;  // 0: from the table's modulus_value column, else 10
    std::string vs, x;         // --vs: the difference curve to this token instead of the map
    double offset = 0;
    int dims = 2, starts = 3;
    std::uint64_t seed = 1;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = group.add_subcommand(
      "magnitude",
      "Magnitude estimation of dissimilarity: per-listener modulus normalisation, geometric means per pair, "
      "dissimilarity matrix and metric SMACOF map");
  auto in = std::make_shared<StatsInput>();
  add_input_options(cmd, *in);
  cmd->add_option("data", opt->data, "Ratings CSV, one row per rated pair")->required();
  cmd->add_option("--subject", opt->subject, "Listener column")->capture_default_str();
  cmd->add_option("--a", opt->first, "First token column")->capture_default_str();
  cmd->add_option("--b", opt->second, "Second token column")->capture_default_str();
  cmd->add_option("--rating", opt->rating, "Magnitude estimate column (> 0)")->capture_default_str();
  cmd->add_option("--modulus-a", opt->modulus_a,
                  "Modulus pair, first token: each listener's ratings are scaled so this pair is rated "
                  "--modulus-value (default: the table's modulus_a/modulus_b columns, as the export writes them; "
                  "without a modulus pair: each listener scaled to the grand geometric mean)");
  cmd->add_option("--modulus-b", opt->modulus_b, "Modulus pair, second token");
  cmd->add_option("--modulus-value", opt->modulus_value,
                  "The number the modulus pair stands for (default: the table's modulus_value column, which the "
                  "export takes from the protocol; else 10)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--dims", opt->dims, "Dimensions of the map")->check(CLI::Range(1, 10))->capture_default_str();
  cmd->add_option("--starts", opt->starts, "SMACOF random starts besides the classical one")
      ->check(CLI::Range(0, 1000))
      ->capture_default_str();
  cmd->add_option("--seed", opt->seed, "Seed of the random starts")->capture_default_str();
  cmd->add_option("--vs", opt->vs,
                  "Instead of the map: each token's mean rated difference to this token (the 2002 study's Fig. 4: "
                  "--vs the real sound --offset -1 --x modes), raw ratings, mean per listener then over listeners");
  cmd->add_option("--offset", opt->offset,
                  "With --vs: added to every rating (-1 puts a 1-10 scale with 1 = identical on Fig. 4's 0-9)")
      ->capture_default_str();
  cmd->add_option("--x", opt->x,
                  "With --vs: column giving each token's x value (e.g. modes, a design factor), read from the row "
                  "where the token is rated against itself");
  cmd->add_option("-o,--output", opt->output,
                  "Write the dissimilarity matrix as square CSV (input of `stats mds`); with --vs the curve "
                  "(x, token, listeners, difference, sd)");
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  cmd->callback([opt, in] {
    if (opt->modulus_a.empty() != opt->modulus_b.empty())
      throw InputError(SourceLocation{}, "--modulus-a and --modulus-b go together: give both tokens of the modulus pair");
    const TidyCsv table = read_stats_table(opt->data, *in);
    if (opt->vs.empty() && (!opt->x.empty() || opt->offset != 0))
      throw InputError(SourceLocation{}, "--x and --offset belong to --vs (the difference to one token)");
    if (!opt->vs.empty()) {
      const MagnitudeColumns columns{opt->subject, opt->first, opt->second, opt->rating};
      return print_difference_curve(difference_to_reference(table, columns, opt->vs, opt->offset, opt->x), opt->vs,
                                    opt->offset, opt->x, opt->output, opt->json);
    }
    const MagnitudeOptions mo = magnitude_options(table, opt->modulus_a, opt->modulus_b, opt->modulus_value);
    const MagnitudeEstimation m =
        magnitude_estimation(table, {opt->subject, opt->first, opt->second, opt->rating}, mo);
    if (std::size_t(opt->dims) >= m.labels.size())
      throw InputError(SourceLocation{}, "--dims " + std::to_string(opt->dims) + ": need fewer dimensions than the " +
                                             std::to_string(m.labels.size()) + " tokens");
    SmacofOptions so;
    so.dims = opt->dims;
    so.random_starts = opt->starts;
    so.seed = opt->seed;
    const SmacofResult map = smacof(m.dissimilarity, so);
    if (!opt->output.empty()) {
      std::vector<std::string> header{"token"};
      header.insert(header.end(), m.labels.begin(), m.labels.end());
      std::string csv = csv::line(header);
      for (std::size_t i = 0; i < m.labels.size(); ++i) {
        std::vector<std::string> cells{m.labels[i]};
        for (std::size_t j = 0; j < m.labels.size(); ++j)
          cells.push_back(fmt("%.17g", m.dissimilarity(Eigen::Index(i), Eigen::Index(j))));
        csv += csv::line(cells);
      }
      write_file_atomically(opt->output, csv);
    }
    if (opt->json) {
      nlohmann::json listeners = nlohmann::json::array();
      for (const auto& l : m.listeners)
        listeners.push_back({{"subject", l.subject}, {"ratings", l.ratings}, {"factor", l.factor},
                             {"modulus_rating", num_json(l.modulus_rating)}, {"geometric_mean", l.geometric_mean}});
      nlohmann::json self = nlohmann::json::array();
      for (double v : m.self_ratings) self.push_back(num_json(v));
      nlohmann::json j = {{"labels", m.labels},
                          {"normalisation", m.modulus ? "modulus" : "geometric_mean"},
                          {"modulus", m.modulus ? nlohmann::json{opt->modulus_a, opt->modulus_b} : nlohmann::json(nullptr)},
                          {"modulus_value", mo.modulus_value},
                          {"grand_geometric_mean", m.grand_geometric_mean},
                          {"listeners", listeners},
                          {"self_ratings", self},
                          {"dissimilarity", matrix_json(m.dissimilarity)},
                          {"dims", opt->dims},
                          {"coords", matrix_json(map.points)},
                          {"stress1", map.stress1},
                          {"raw_stress", map.raw_stress},
                          {"starts", opt->starts + 1},
                          {"seed", opt->seed}};
      std::cout << j.dump() << "\n";
      return;
    }
    std::printf("magnitude estimation: %zu listeners, %zu tokens, normalised by %s\n", m.listeners.size(),
                m.labels.size(),
                m.modulus ? ("the modulus pair (" + opt->modulus_a + ", " + opt->modulus_b + ") = " +
                             fmt("%g", mo.modulus_value)).c_str()
                          : "each listener's geometric mean");
    for (const auto& l : m.listeners)
      std::printf("  %-16s %4zu ratings  factor %.4g\n", l.subject.c_str(), l.ratings, l.factor);
    std::printf("SMACOF map in %d dimensions: stress-1 = %.4f\n", opt->dims, map.stress1);
    for (std::size_t i = 0; i < m.labels.size(); ++i) {
      std::printf("%-20s", m.labels[i].c_str());
      for (int k = 0; k < opt->dims; ++k) std::printf(" %10.4f", map.points(Eigen::Index(i), k));
      std::printf("\n");
    }
  });
}

}  // namespace ms::cli
