// The part the staircase and method-of-limits views share: a trial of steps, each playing the
// reference and then the stimulus with one parameter at the session's level (rendered on a worker,
// the play buttons off until it is ready), a button that plays them in order, and a choice cleared
// for every step. Each view places the sounds (staircase: reference, A, B; limits: reference, comparison).
#pragma once
#include <QTimer>

#include <functional>
#include <string>

#include "studyapp/gui/async_render.hpp"
#include "studyapp/gui/trial_view.hpp"

namespace ms::gui {

class LevelSeriesView : public TrialView {
 public:
  LevelSeriesView(StudyController& c, QWidget* parent, const StimulusRef& stimulus,
                  const std::optional<StimulusRef>& reference, std::string parameter)
      : TrialView(c, parent), stimulus_(stimulus.name), parameter_(std::move(parameter)) {
    reference_name_ = reference ? reference->name : stimulus.name;
    reference_ = c.samples(reference_name_);
  }

 protected:
  bool ready() const override { return comparison_ready_ && choices_->checkedId() >= 0; }

  // The "play in order" button over `count` sounds (400 ms between them).
  void add_sequence_button(const QString& text, int count) {
    auto* sequence = new QPushButton(text, body());
    sequence->setObjectName("play-sequence");
    connect(sequence, &QPushButton::clicked, this, [this] { play_sequence(0); });
    layout_->addWidget(sequence);
    connect(&controller_, &StudyController::playingChanged, this, [this, count](bool playing) {
      if (!playing && sequence_next_ > 0 && sequence_next_ < count)
        QTimer::singleShot(400, this, [this] { play_sequence(sequence_next_); });
    });
  }

  // A new step at `level`: the choice cleared, the sounds off until place(reference, comparison) ran.
  void start_level(double level, std::size_t sounds,
                   std::function<std::vector<Sound>(const Sound&, const Sound&)> place) {
    comparison_ready_ = false;
    if (QAbstractButton* b = choices_->checkedButton()) {
      choices_->setExclusive(false);
      b->setChecked(false);
      choices_->setExclusive(true);
    }
    for (std::size_t i = 0; i < sounds; ++i) play_button(i)->setEnabled(false);
    if (!controller_.has_session() || controller_.previewing()) return;
    const std::string set = override_text(parameter_, level);
    render_async(controller_.cache(), stimulus_, {set}, this,
                 [this, set, sounds, place](Samples samples, double, const std::string& error) {
                   if (!error.empty()) return step_label_->setText(QString::fromStdString("cannot render: " + error));
                   controller_.set_sounds(place(Sound{reference_name_, reference_}, Sound{stimulus_ + "@" + set, samples}));
                   comparison_ready_ = true;
                   for (std::size_t i = 0; i < sounds; ++i) play_button(i)->setEnabled(true);
                   refresh();
                 });
    refresh();
  }

  // Before committing a step: stops the sequence and the sound; false while Next may not be pressed.
  bool end_step() {
    if (!gate().may_send) return false;
    sequence_next_ = 0;
    controller_.stop();
    return true;
  }

  std::string stimulus_, parameter_;
  std::string reference_name_;  // the block's `reference`, or the stimulus as defined
  Samples reference_;
  QButtonGroup* choices_ = nullptr;
  QLabel* step_label_ = nullptr;

 private:
  void play_sequence(int from) {
    if (!comparison_ready_) return;
    sequence_next_ = from + 1;
    controller_.play(static_cast<std::size_t>(from));
  }

  bool comparison_ready_ = false;
  int sequence_next_ = 0;
};

}  // namespace ms::gui
