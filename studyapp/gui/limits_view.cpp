// Descending method of limits: each pair of the series plays the reference (the block's `reference`,
// default the stimulus as defined), then the comparison — the stimulus with the parameter at the
// series' level — and asks whether the second sound differs from the first. The session lowers the
// level after every "same" and ends the series at the first "different"; the view plays the two sounds
// (both must be heard before Next, answer_gate) and reports the button pressed. The level is not
// shown: the participant would learn where the series is heading.
#include "studyapp/gui/level_series_view.hpp"

namespace ms::gui {

namespace {

class LimitsView : public LevelSeriesView {
 public:
  LimitsView(StudyController& c, QWidget* parent, const LimitsBlock& block)
      : LevelSeriesView(c, parent, block.stimulus, block.reference, block.parameter), start_(block.start) {
    setObjectName("limits-view");
    add_step_widgets("Listen to the reference, then to the second sound. Do you hear a change?",
                     QString::fromUtf8("\u25B6 Play reference, then the second sound"), {"Reference", "Second sound"},
                     {"Same", "Different"}, {"same", "different"}, [this] { answer_step(); });
    start_step();
  }

 private:
  void start_step() {
    const bool live = controller_.has_session() && !controller_.previewing();
    const std::size_t pair = live ? controller_.session().limits().levels().size() : 0;
    step_label_->setText(QString("Pair %1 of this series \u2014 the series ends when you hear a change.").arg(pair + 1));
    start_level(live ? controller_.session().limits().level() : start_, 2,
                [](const Sound& reference, const Sound& comparison) { return std::vector<Sound>{reference, comparison}; });
  }

  void answer_step() {
    if (!end_step()) return;
    if (!controller_.limits_step(choices_->checkedId() == 1)) return;  // the series ended: the next trial shows
    start_step();
  }

  double start_;
};

}  // namespace

TrialView* make_limits_view(StudyController& c, QWidget* parent) {
  const auto* spec = std::get_if<LimitsBlock>(&c.block().body);
  return new LimitsView(c, parent, spec ? *spec : LimitsBlock{});
}

}  // namespace ms::gui
