// Adaptive staircase (three intervals): each step plays the reference (the block's `reference`, default
// the stimulus as defined), then A and B — one of them the reference again, the other the stimulus with
// the tracked parameter at the track's level (rendered on a worker) — and asks which of A/B is the same
// as the reference. Which interval holds the comparison is the session's draw, and the session scores the
// interval chosen: the view plays the intervals and reports the button pressed. Each answer is one Session
// step; the trial ends when the track does. The view shows the steps and reversals so far of their maxima,
// and (with `feedback: true`) whether each answer was right.
#include "studyapp/gui/level_series_view.hpp"

namespace ms::gui {

namespace {

class StaircaseView : public LevelSeriesView {
 public:
  StaircaseView(StudyController& c, QWidget* parent, const StaircaseBlock& block)
      : LevelSeriesView(c, parent, block.stimulus, block.reference, block.parameter), block_(block) {
    setObjectName("staircase-view");
    add_step_widgets("Listen to the reference, then to A and B. Which of A and B is the same as the reference?",
                     QString::fromUtf8("\u25B6 Play reference, A, B"), {"Reference", "A", "B"}, {"A", "B"}, {"A", "B"},
                     [this] { answer_step(); });
    start_step();
  }

 private:
  void start_step() {
    const bool live = controller_.has_session() && !controller_.previewing();
    const std::size_t step = live ? controller_.session().staircase().levels().size() : 0;
    const std::size_t reversals = live ? controller_.session().staircase().reversals() : 0;
    const bool in_b = (live ? controller_.session().staircase_comparison() : AbInterval::b) == AbInterval::b;
    step_label_->setText(QString("Step %1 of at most %2 \u00B7 %3 of %4 turning points \u2014 this part ends after "
                                 "%4 turning points.")
                             .arg(step + 1)
                             .arg(StaircaseTrack::kMaxSteps)
                             .arg(reversals)
                             .arg(block_.reversals));
    start_level(live ? controller_.session().staircase().level() : block_.start, 3,
                [in_b](const Sound& reference, const Sound& comparison) {
                  return std::vector<Sound>{reference, in_b ? reference : comparison, in_b ? comparison : reference};
                });
  }

  void answer_step() {
    if (!end_step()) return;
    const AbInterval chosen = choices_->checkedId() == 1 ? AbInterval::b : AbInterval::a;
    const bool feedback = controller_.block().feedback;
    const StaircaseReply reply = controller_.staircase_step(chosen);
    if (!reply.goes_on) return;  // the track ended: the window shows the next trial
    if (feedback) show_feedback(reply.correct ? "Right." : "Not quite.", reply.correct);
    start_step();
  }

  StaircaseBlock block_;
};

}  // namespace

TrialView* make_staircase_view(StudyController& c, QWidget* parent) {
  const auto* spec = std::get_if<StaircaseBlock>(&c.block().body);
  return new StaircaseView(c, parent, spec ? *spec : StaircaseBlock{});
}

}  // namespace ms::gui
