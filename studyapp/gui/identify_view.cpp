// Identification: play the sound, choose one of the block's n labels (keys 1..n).
#include "studyapp/gui/trial_view.hpp"

namespace ms::gui {

namespace {

class IdentifyView : public TrialView {
 public:
  IdentifyView(StudyController& c, QWidget* parent) : TrialView(c, parent) {
    const auto* spec = std::get_if<IdentifyBlock>(&c.block().body);
    c.set_sounds(sounds_of(c, c.trial().stimuli));
    add_prompt("What do you hear? Choose the best label.");
    add_sound_buttons({"Sound"}, false);
    QStringList labels;
    if (spec)
      for (const std::string& l : spec->labels) labels << QString::fromStdString(l);
    choices_ = add_choices(labels, labels);
    add_next([this, labels] { return IdentifyAnswer{labels[choices_->checkedId()].toStdString()}; });
  }

 protected:
  bool ready() const override { return choices_->checkedId() >= 0; }

 private:
  QButtonGroup* choices_ = nullptr;
};

}  // namespace

TrialView* make_identify_view(StudyController& c, QWidget* parent) { return new IdentifyView(c, parent); }

}  // namespace ms::gui
