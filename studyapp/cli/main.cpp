// modalstudy: the command line of ModalStudy (see README and ../shared/DESIGN.md §5).
// Bad input ends with one line on stderr naming file:line:column and exit code 2.
#include <exception>
#include <iostream>

#include "studyapp/cli/commands.hpp"
#include "synthesis/input_error.hpp"

int main(int argc, char** argv) {
  CLI::App app{"ModalStudy: perceptual studies of modal impact sounds"};
  app.set_version_flag("--version", "modalstudy 0.1.0");
  app.require_subcommand(1);
  ms::cli::register_synth(app);
  ms::cli::register_stimuli(app);
  ms::cli::register_bench(app);
  ms::cli::register_materials(app);
  ms::cli::register_fit_damping(app);
  ms::cli::register_validate_damping(app);
  ms::cli::register_extract(app);
  ms::cli::register_prune(app);
  ms::cli::register_stats(app);
  ms::cli::register_plot(app);
  ms::cli::register_export(app);
  ms::cli::register_protocol(app);
  ms::cli::register_audit(app);
  ms::cli::register_audit_generate(app);
  ms::cli::register_compare(app);
  ms::cli::register_estimate(app);
  ms::cli::register_serve(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help and --version
    std::cerr << "modalstudy: " << e.what() << "\n";  // a bad option is bad input: one line, exit 2
    return 2;
  } catch (const ms::InputError& e) {
    std::cerr << "modalstudy: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "modalstudy: error: " << e.what() << "\n";
    return 3;
  }
  return 0;
}
