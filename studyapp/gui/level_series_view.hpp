// The part the staircase, method-of-limits and token views share: a trial of steps, each playing the
// reference and then the stimulus with one parameter at the session's level (rendered on a worker,
// the play buttons off until it is ready; for tokens the reference is the stimulus at a level too), a
// button that plays them in order, and a choice cleared for every step. Each view places the sounds
// (staircase: reference, A, B; limits and tokens: reference, comparison).
#pragma once
#include <functional>
#include <memory>
#include <optional>
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

  bool sequence_playable() const override { return comparison_ready_; }

  // The step's widgets: the task, the play-in-order button, one play button per sound (silent
  // placeholders until the first step is rendered), the choices, the step line and Next.
  void add_step_widgets(const QString& prompt, const QString& sequence, const QStringList& sounds,
                        const QStringList& choice_labels, const QStringList& choice_names, std::function<void()> on_next) {
    add_prompt(prompt);
    std::vector<Sound> placeholders;
    for (const QString& label : sounds) placeholders.push_back(Sound{label.toStdString(), reference_});
    controller_.set_sounds(std::move(placeholders));
    add_sequence_button(sequence, int(sounds.size()));
    add_sound_buttons(sounds, false);
    choices_ = add_choices(choice_labels, choice_names);
    step_label_ = new QLabel(body());
    step_label_->setObjectName("step");
    layout_->addWidget(step_label_);
    add_next_action(std::move(on_next), "Next");
  }

  // A new step at `level`: the choice cleared, the sounds off until place(reference, comparison) ran.
  // With `reference_level` (token series) the reference is the stimulus at that level too, not the
  // block's fixed reference; both are rendered before the step is playable.
  void start_level(double level, std::size_t sounds, std::function<std::vector<Sound>(const Sound&, const Sound&)> place,
                   std::optional<double> reference_level = std::nullopt) {
    comparison_ready_ = false;
    if (QAbstractButton* b = choices_->checkedButton()) {
      choices_->setExclusive(false);
      b->setChecked(false);
      choices_->setExclusive(true);
    }
    for (std::size_t i = 0; i < sounds; ++i) play_button(i)->setEnabled(false);
    if (!controller_.has_session() || controller_.previewing()) return;
    struct Pending {
      int left = 1;
      Sound reference, comparison;
    };
    auto step = std::make_shared<Pending>();
    step->reference = Sound{reference_name_, reference_};
    const auto one_done = [this, step, sounds, place] {
      if (--step->left > 0) return;
      controller_.set_sounds(place(step->reference, step->comparison));
      comparison_ready_ = true;
      for (std::size_t i = 0; i < sounds; ++i) play_button(i)->setEnabled(true);
      refresh();
    };
    const auto render = [this, one_done](double at, Sound Pending::*into, std::shared_ptr<Pending> pending) {
      const std::string set = override_text(parameter_, at);
      render_async(controller_.cache(), stimulus_, {set}, this,
                   [this, set, into, pending, one_done](Samples samples, double, const std::string& error) {
                     if (!error.empty()) return step_label_->setText(QString::fromStdString("cannot render: " + error));
                     (*pending).*into = Sound{stimulus_ + "@" + set, samples};
                     one_done();
                   });
    };
    if (reference_level) step->left = 2;
    render(level, &Pending::comparison, step);
    if (reference_level) render(*reference_level, &Pending::reference, step);
    refresh();
  }

  // Before committing a step: stops the sequence and the sound; false while Next may not be pressed.
  bool end_step() {
    if (!gate().may_send) return false;
    stop_sequence();
    controller_.stop();
    return true;
  }

  std::string stimulus_, parameter_;
  std::string reference_name_;  // the block's `reference`, or the stimulus as defined
  Samples reference_;
  QButtonGroup* choices_ = nullptr;
  QLabel* step_label_ = nullptr;

 private:
  bool comparison_ready_ = false;
};

}  // namespace ms::gui
