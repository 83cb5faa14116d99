// Adaptive token series (van den Doel et al. 2002, Exp. 2): each step plays the current reference token,
// then the next token (one mode fewer than the last one compared), both the block's stimulus with its
// first K modes, and asks whether they sound different. The session keeps the rule (a "different"
// comparison becomes the reference) and ends the series after the last token; the view plays the two
// sounds (both heard before Next, answer_gate) and reports the button pressed. The numbers of modes are
// not shown, only how far the series has come.
#include "studyapp/gui/level_series_view.hpp"

namespace ms::gui {

namespace {

class TokensView : public LevelSeriesView {
 public:
  TokensView(StudyController& c, QWidget* parent, const TokensBlock& block)
      : LevelSeriesView(c, parent, block.stimulus, std::nullopt, kTokenParameter), from_(block.from), to_(block.to) {
    setObjectName("tokens-view");
    add_step_widgets("Listen to the reference, then to the next sound. Do they sound different?",
                     QString::fromUtf8("\u25B6 Play the reference, then the next sound"), {"Reference", "Next sound"},
                     {"Same", "Different"}, {"same", "different"}, [this] { answer_step(); });
    start_step();
  }

 private:
  void start_step() {
    const bool live = controller_.has_session() && !controller_.previewing();
    const TokenSeries preview(from_, to_);
    const TokenSeries& series = live ? controller_.session().tokens() : preview;
    step_label_->setText(QString("Comparison %1 of %2 \u2014 the series ends with the simplest sound.")
                             .arg(series.different().size() + 1)
                             .arg(from_ - to_));
    start_level(series.comparison(), 2,
                [](const Sound& reference, const Sound& comparison) { return std::vector<Sound>{reference, comparison}; },
                double(series.reference()));
  }

  void answer_step() {
    if (!end_step()) return;
    if (!controller_.tokens_step(choices_->checkedId() == 1)) return;  // the series ended: the next trial shows
    start_step();
  }

  int from_, to_;
};

}  // namespace

TrialView* make_tokens_view(StudyController& c, QWidget* parent) {
  const auto* spec = std::get_if<TokensBlock>(&c.block().body);
  return new TokensView(c, parent, spec ? *spec : TokensBlock{{}, 2, 1, {}, {}});
}

}  // namespace ms::gui
