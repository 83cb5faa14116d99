// Descending method of limits: each trial of the series plays the reference (the block's `reference`,
// default the stimulus as defined), then the comparison — the stimulus with the parameter at the
// series' level, rendered on a worker — and asks whether the second sound differs from the first. The
// session lowers the level after every "same" and ends the series at the first "different"; the view
// plays the two sounds (both must be heard before Next, answer_gate) and reports the button pressed.
// The level is not shown: the participant would learn where the series is heading.
#include <QTimer>

#include "studyapp/gui/async_render.hpp"
#include "studyapp/gui/trial_view.hpp"

namespace ms::gui {

namespace {

class LimitsView : public TrialView {
 public:
  LimitsView(StudyController& c, QWidget* parent) : TrialView(c, parent) {
    const auto* spec = std::get_if<LimitsBlock>(&c.block().body);
    if (spec) block_ = *spec;
    setObjectName("limits-view");
    add_prompt("Listen to the reference, then to the second sound. Do you hear a change?");
    reference_name_ = block_.reference ? block_.reference->name : block_.stimulus.name;
    reference_ = c.samples(reference_name_);
    c.set_sounds({Sound{"reference", reference_}, Sound{"comparison", reference_}});
    auto* sequence = new QPushButton(QString::fromUtf8("\u25B6 Play reference, then the second sound"), body());
    sequence->setObjectName("play-sequence");
    connect(sequence, &QPushButton::clicked, this, [this] { play_sequence(0); });
    layout_->addWidget(sequence);
    add_sound_buttons({"Reference", "Second sound"}, false);
    choices_ = add_choices({"Same", "Different"}, {"same", "different"});
    step_label_ = new QLabel(body());
    step_label_->setObjectName("step");
    layout_->addWidget(step_label_);
    add_next_action([this] { answer_step(); }, "Next");
    connect(&controller_, &StudyController::playingChanged, this, [this](bool playing) {
      if (!playing && sequence_next_ == 1) QTimer::singleShot(400, this, [this] { play_sequence(1); });
    });
    start_step();
  }

 protected:
  bool ready() const override { return comparison_ready_ && choices_->checkedId() >= 0; }

 private:
  void start_step() {
    const bool live = controller_.has_session() && !controller_.previewing();
    const std::size_t step = live ? controller_.session().limits().levels().size() : 0;
    level_ = live ? controller_.session().limits().level() : block_.start;
    comparison_ready_ = false;
    if (QAbstractButton* b = choices_->checkedButton()) {
      choices_->setExclusive(false);
      b->setChecked(false);
      choices_->setExclusive(true);
    }
    step_label_->setText(QString("Pair %1 of this series \u2014 the series ends when you hear a change.").arg(step + 1));
    for (std::size_t i = 0; i < 2; ++i) play_button(i)->setEnabled(false);
    if (!live) return;
    render_async(controller_.cache(), block_.stimulus.name, {override_text(block_.parameter, level_)}, this,
                 [this](Samples samples, double, const std::string& error) {
                   if (!error.empty()) return step_label_->setText(QString::fromStdString("cannot render: " + error));
                   const std::string name = block_.stimulus.name + "@" + override_text(block_.parameter, level_);
                   controller_.set_sounds({Sound{reference_name_, reference_}, Sound{name, samples}});
                   comparison_ready_ = true;
                   for (std::size_t i = 0; i < 2; ++i) play_button(i)->setEnabled(true);
                   refresh();
                 });
    refresh();
  }

  void play_sequence(int from) {
    if (!comparison_ready_) return;
    sequence_next_ = from + 1;
    controller_.play(static_cast<std::size_t>(from));
  }

  void answer_step() {
    if (!gate().may_send) return;
    sequence_next_ = 0;
    controller_.stop();
    if (!controller_.limits_step(choices_->checkedId() == 1)) return;  // the series ended: the next trial shows
    start_step();
  }

  LimitsBlock block_;
  std::string reference_name_;  // the block's `reference`, or the stimulus as defined
  Samples reference_;
  QButtonGroup* choices_ = nullptr;
  QLabel* step_label_ = nullptr;
  double level_ = 0.0;
  bool comparison_ready_ = false;
  int sequence_next_ = 0;
};

}  // namespace

TrialView* make_limits_view(StudyController& c, QWidget* parent) { return new LimitsView(c, parent); }

}  // namespace ms::gui
