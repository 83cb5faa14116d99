// studyapp: runs a listening test in a window (README "For experimenters: running a study").
// --autopilot runs headless and never creates a QApplication, so it works without a display.
#include <QApplication>

#include "studyapp/gui/app_options.hpp"
#include "studyapp/gui/experimenter_window.hpp"
#include "studyapp/gui/main_window.hpp"

int main(int argc, char** argv) {
  ms::gui::AppOptions options;
  if (const auto code = ms::gui::parse_command_line(argc, argv, options)) return *code;
  if (options.autopilot_seed) return ms::gui::run_autopilot_command(options);
  if (!options.protocol_path.empty() && !ms::gui::report_protocol_problems(options)) return 2;
  if (ms::gui::report_participant_refusal(options)) return 2;

  QApplication app(argc, argv);
  QApplication::setApplicationName("studyapp");
  if (!options.experimenter_db.empty()) {
    ms::gui::ExperimenterWindow window(QString::fromStdString(options.experimenter_db));
    window.show();
    return QApplication::exec();
  }
  ms::gui::MainWindow window(options);
  window.show();
  return QApplication::exec();
}
