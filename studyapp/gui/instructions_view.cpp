// The instructions page: the protocol's text and Next (answer "ok").
#include "studyapp/gui/trial_view.hpp"

namespace ms::gui {

namespace {

class InstructionsView : public TrialView {
 public:
  InstructionsView(StudyController& c, QWidget* parent) : TrialView(c, parent) {
    const auto* spec = std::get_if<InstructionsBlock>(&c.block().body);
    add_prompt(QString::fromStdString(spec ? spec->text : std::string()))->setObjectName("instructions");
    add_next([] { return InstructionsAnswer{}; }, "Continue");
  }
};

}  // namespace

TrialView* make_instructions_view(StudyController& c, QWidget* parent) { return new InstructionsView(c, parent); }

}  // namespace ms::gui
