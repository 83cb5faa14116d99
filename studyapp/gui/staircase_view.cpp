// Adaptive staircase (three intervals): each step plays the reference (the block's `reference`, default
// the stimulus as defined), then A and B — one of them the reference again, the other the stimulus with
// the tracked parameter at the track's level (rendered on a worker) — and asks which of A/B is the same
// as the reference. Which interval holds the comparison is the session's draw, and the session scores the
// interval chosen: the view plays the intervals and reports the button pressed. Each answer is one Session
// step; the trial ends when the track does. The view shows the steps and reversals so far of their maxima,
// and (with `feedback: true`) whether each answer was right.
#include <QTimer>

#include "studyapp/gui/async_render.hpp"
#include "studyapp/gui/trial_view.hpp"

namespace ms::gui {

namespace {

class StaircaseView : public TrialView {
 public:
  StaircaseView(StudyController& c, QWidget* parent) : TrialView(c, parent) {
    const auto* spec = std::get_if<StaircaseBlock>(&c.block().body);
    if (spec) block_ = *spec;
    setObjectName("staircase-view");
    add_prompt("Listen to the reference, then to A and B. Which of A and B is the same as the reference?");
    reference_name_ = block_.reference ? block_.reference->name : block_.stimulus.name;
    reference_ = c.samples(reference_name_);
    c.set_sounds({Sound{"reference", reference_}, Sound{"A", reference_}, Sound{"B", reference_}});
    auto* sequence = new QPushButton(QString::fromUtf8("\u25B6 Play reference, A, B"), body());
    sequence->setObjectName("play-sequence");
    connect(sequence, &QPushButton::clicked, this, [this] { play_sequence(0); });
    layout_->addWidget(sequence);
    add_sound_buttons({"Reference", "A", "B"}, false);
    choices_ = add_choices({"A", "B"}, {"A", "B"});
    step_label_ = new QLabel(body());
    step_label_->setObjectName("step");
    layout_->addWidget(step_label_);
    add_next_action([this] { answer_step(); }, "Next");
    connect(&controller_, &StudyController::playingChanged, this, [this](bool playing) {
      if (!playing && sequence_next_ > 0 && sequence_next_ < 3)
        QTimer::singleShot(400, this, [this] { play_sequence(sequence_next_); });
    });
    start_step();
  }

 protected:
  bool ready() const override { return comparison_ready_ && choices_->checkedId() >= 0; }

 private:
  void start_step() {
    const bool live = controller_.has_session() && !controller_.previewing();
    const std::size_t step = live ? controller_.session().staircase().levels().size() : 0;
    const std::size_t reversals = live ? controller_.session().staircase().reversals() : 0;
    comparison_ = live ? controller_.session().staircase_comparison() : AbInterval::b;
    level_ = live ? controller_.session().staircase().level() : block_.start;
    comparison_ready_ = false;
    if (QAbstractButton* b = choices_->checkedButton()) {
      choices_->setExclusive(false);
      b->setChecked(false);
      choices_->setExclusive(true);
    }
    step_label_->setText(QString("Step %1 of at most %2 \u00B7 %3 of %4 turning points \u2014 this part ends after "
                                 "%4 turning points.")
                             .arg(step + 1)
                             .arg(StaircaseTrack::kMaxSteps)
                             .arg(reversals)
                             .arg(block_.reversals));
    for (std::size_t i = 0; i < 3; ++i) play_button(i)->setEnabled(false);
    if (!live) return;
    render_async(controller_.cache(), block_.stimulus.name, {override_text(block_.parameter, level_)}, this,
                 [this](Samples samples, double, const std::string& error) {
                   if (!error.empty()) return step_label_->setText(QString::fromStdString("cannot render: " + error));
                   const std::string name = block_.stimulus.name + "@" + override_text(block_.parameter, level_);
                   const Sound reference{reference_name_, reference_}, comparison{name, samples};
                   const bool in_b = comparison_ == AbInterval::b;
                   controller_.set_sounds({reference, in_b ? reference : comparison, in_b ? comparison : reference});
                   comparison_ready_ = true;
                   for (std::size_t i = 0; i < 3; ++i) play_button(i)->setEnabled(true);
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
    const AbInterval chosen = choices_->checkedId() == 1 ? AbInterval::b : AbInterval::a;
    const bool feedback = controller_.block().feedback;
    const StaircaseReply reply = controller_.staircase_step(chosen);
    if (!reply.goes_on) return;  // the track ended: the window shows the next trial
    if (feedback) show_feedback(reply.correct ? "Right." : "Not quite.", reply.correct);
    start_step();
  }

  StaircaseBlock block_;
  std::string reference_name_;  // the block's `reference`, or the stimulus as defined
  Samples reference_;
  QButtonGroup* choices_ = nullptr;
  QLabel* step_label_ = nullptr;
  double level_ = 0.0;
  AbInterval comparison_ = AbInterval::b;  // where the session put the comparison in this step
  bool comparison_ready_ = false;
  int sequence_next_ = 0;
};

}  // namespace

TrialView* make_staircase_view(StudyController& c, QWidget* parent) { return new StaircaseView(c, parent); }

}  // namespace ms::gui
