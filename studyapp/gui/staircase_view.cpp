// Adaptive staircase (three intervals): each step plays the reference (the block's `reference`, default
// the stimulus as defined), then A and B — one of them the reference again, the other the stimulus with
// the tracked parameter at the track's level (rendered on a worker) — and asks which of A/B is the same
// as the reference. Each answer is one Session step; the
// trial ends when the track does. Which interval holds the comparison is drawn from the session's seed.
#include <QTimer>

#include <random>

#include "studyapp/gui/async_render.hpp"
#include "studyapp/gui/trial_view.hpp"

namespace ms::gui {

namespace {

class StaircaseView : public TrialView {
 public:
  StaircaseView(StudyController& c, QWidget* parent) : TrialView(c, parent) {
    const auto* body = std::get_if<StaircaseBlock>(&c.session().current_block().body);
    if (body) block_ = *body;
    setObjectName("staircase-view");
    require_all_played_ = true;
    add_prompt("Listen to the reference, then to A and B. Which of A and B is the same as the reference?");
    reference_name_ = block_.reference ? block_.reference->name : block_.stimulus.name;
    reference_ = c.cache().samples(reference_name_);
    c.set_sounds({Sound{"reference", reference_}, Sound{"A", reference_}, Sound{"B", reference_}});
    auto* sequence = new QPushButton(QString::fromUtf8("\u25B6 Play reference, A, B"), this);
    sequence->setObjectName("play-sequence");
    connect(sequence, &QPushButton::clicked, this, [this] { play_sequence(0); });
    layout_->addWidget(sequence);
    add_sound_buttons({"Reference", "A", "B"}, false);
    choices_ = add_choices({"A", "B"}, {"A", "B"});
    step_label_ = new QLabel(this);
    step_label_->setObjectName("step");
    layout_->addWidget(step_label_);
    add_next_action([this] { answer_step(); }, "Answer");
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
    const std::size_t step = controller_.session().staircase().levels().size();
    std::mt19937_64 rng(controller_.session().schedule().seed ^ (0x9e3779b97f4a7c15ULL * (step + 1)));
    comparison_in_b_ = (rng() & 1U) != 0;
    level_ = controller_.session().staircase().level();
    comparison_ready_ = false;
    if (QAbstractButton* b = choices_->checkedButton()) {
      choices_->setExclusive(false);
      b->setChecked(false);
      choices_->setExclusive(true);
    }
    step_label_->setText(QString("Step %1").arg(step + 1));
    for (std::size_t i = 0; i < 3; ++i) play_button(i)->setEnabled(false);
    render_async(controller_.cache(), block_.stimulus.name, {override_text(block_.parameter, level_)}, this,
                 [this](Samples samples, double, const std::string& error) {
                   if (!error.empty()) return step_label_->setText(QString::fromStdString("cannot render: " + error));
                   const std::string name = block_.stimulus.name + "@" + override_text(block_.parameter, level_);
                   const Sound reference{reference_name_, reference_}, comparison{name, samples};
                   controller_.set_sounds({reference, comparison_in_b_ ? reference : comparison,
                                           comparison_in_b_ ? comparison : reference});
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
    if (!ready() || !controller_.played_all()) return;
    sequence_next_ = 0;
    controller_.stop();
    const bool chose_b = choices_->checkedId() == 1;
    const bool correct = chose_b != comparison_in_b_;  // the reference's copy is the one without the comparison
    if (controller_.staircase_step(correct)) start_step();
  }

  StaircaseBlock block_;
  std::string reference_name_;  // the block's `reference`, or the stimulus as defined
  Samples reference_;
  QButtonGroup* choices_ = nullptr;
  QLabel* step_label_ = nullptr;
  double level_ = 0.0;
  bool comparison_in_b_ = false, comparison_ready_ = false;
  int sequence_next_ = 0;
};

}  // namespace

TrialView* make_staircase_view(StudyController& c, QWidget* parent) { return new StaircaseView(c, parent); }

}  // namespace ms::gui
