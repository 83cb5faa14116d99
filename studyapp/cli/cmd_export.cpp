// modalstudy export RESULTS.sqlite -o DIR [--format tidy|webmushra]: tidy responses.csv (one row per
// response) + study.json, or webMUSHRA's result tables.
#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>
#include <memory>

#include "studyapp/cli/commands.hpp"
#include "studyapp/core/export.hpp"
#include "studyapp/core/webmushra_results.hpp"

namespace ms::cli {

void register_export(CLI::App& app) {
  struct Options {
    std::string db, out_dir, format = "tidy";
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand(
      "export", "Export a results database: DIR/responses.csv (tidy, one row per response), study.json, trials.csv "
      "(stimulus hashes), events.csv and one tidy table per block type (mushra.csv, identify.csv, ...)");
  cmd->add_option("results", opt->db, "Results database written by studyapp: a .sqlite file or a postgresql:// URI")->required();
  cmd->add_option("-o,--output", opt->out_dir, "Output folder (created if missing)")->required();
  cmd->add_flag("--json", opt->json, "Print one JSON object");
  cmd->add_option("--format", opt->format,
                  "tidy (default), or webmushra: webMUSHRA's result tables (mushra.csv, paired_comparison.csv, lss.csv)")
      ->check(CLI::IsMember({"tidy", "webmushra"}));
  cmd->callback([opt] {
    if (opt->format == "webmushra") {
      const ExportSummary s = export_webmushra(opt->db, opt->out_dir);
      for (const std::string& n : s.notices) std::cerr << "notice: " << opt->db << ": " << n << "\n";
      if (opt->json)
        std::cout << nlohmann::json{{"responses", s.responses}, {"tables", s.tables}, {"notices", s.notices}}.dump() << "\n";
      else {
        std::string tables;
        for (const auto& t : s.tables) tables += " " + t;
        std::printf("webMUSHRA tables in %s:%s\n", opt->out_dir.c_str(), tables.empty() ? " none" : tables.c_str());
      }
      return;
    }
    const ExportSummary s = export_results(opt->db, opt->out_dir);
    for (const std::string& n : s.notices) std::cerr << "notice: " << opt->db << ": " << n << "\n";
    if (opt->json)
      std::cout << nlohmann::json{{"responses", s.responses}, {"csv", s.csv_path}, {"study_json", s.json_path},
                                  {"tables", s.tables}, {"notices", s.notices}}
                       .dump()
                << "\n";
    else {
      std::printf("exported %zu responses to %s and %s\n", s.responses, s.csv_path.c_str(), s.json_path.c_str());
      std::string tables;
      for (const auto& t : s.tables) tables += " " + t;
      std::printf("tidy tables:%s trials.csv events.csv\n", tables.c_str());
    }
  });
}

}  // namespace ms::cli
