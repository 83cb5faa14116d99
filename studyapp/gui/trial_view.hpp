// The base of every trial view: prompt, play buttons wired to the controller (space = play/stop), exclusive
// choice buttons (keys 1..n), and the Next button (Enter) that commits the answer. A view only builds its
// widgets and its answer; whether Next is enabled is derived from the controller and the widgets' state.
#pragma once
#include <QBoxLayout>
#include <QButtonGroup>
#include <QLabel>
#include <QPushButton>
#include <QStringList>
#include <QWidget>

#include <functional>
#include <vector>

#include <nlohmann/json.hpp>

#include "studyapp/gui/study_controller.hpp"

namespace ms::gui {

class TrialView : public QWidget {
 public:
  TrialView(StudyController& controller, QWidget* parent);

 protected:
  QLabel* add_prompt(const QString& text, QBoxLayout* into = nullptr);
  // Play buttons for the controller's sounds, objectName "play-<i>". seamless: while a sound plays, another
  // button switches to it at the same position (MUSHRA). with_loop adds the loop check box.
  QWidget* add_sound_buttons(const QStringList& labels, bool seamless, bool with_loop = false,
                             QBoxLayout* into = nullptr, bool vertical = false);
  QPushButton* play_button(std::size_t index) const { return play_buttons_.at(index); }
  // Exclusive checkable buttons (objectName "choice-<name>"), keys 1..n select.
  QButtonGroup* add_choices(const QStringList& labels, const QStringList& names, QBoxLayout* into = nullptr);
  // The Next button (objectName "next", Enter/Return) committing answer().
  void add_next(std::function<nlohmann::json()> answer, const QString& text = "Next");
  void add_next_action(std::function<void()> on_next, const QString& text);  // the same button, own action
  void refresh();                                   // re-derive Next and play-button states
  virtual bool ready() const { return true; }       // the widgets hold a complete answer
  virtual void on_sound_played(int /*index*/) {}

  StudyController& controller_;
  QVBoxLayout* layout_;
  QPushButton* next_ = nullptr;
  bool require_all_played_ = false;                 // "listen to all before rating"
  bool digits_play_sounds_ = false;                 // keys 1..n play the sounds (views without choices)
  QLabel* hint_ = nullptr;

 private:
  void press_play(std::size_t index, bool seamless);
  void play_or_stop();
  std::vector<QPushButton*> play_buttons_;
  QStringList sound_labels_;
};

// The view for the controller's current trial (by block type).
TrialView* make_trial_view(StudyController& controller, QWidget* parent);

// One factory per block type (one file each).
TrialView* make_instructions_view(StudyController& c, QWidget* parent);
TrialView* make_ab_view(StudyController& c, QWidget* parent);
TrialView* make_mushra_view(StudyController& c, QWidget* parent);
TrialView* make_magnitude_view(StudyController& c, QWidget* parent);
TrialView* make_identify_view(StudyController& c, QWidget* parent);
TrialView* make_rating_view(StudyController& c, QWidget* parent);
TrialView* make_adjust_view(StudyController& c, QWidget* parent);
TrialView* make_staircase_view(StudyController& c, QWidget* parent);
TrialView* make_questionnaire_view(StudyController& c, QWidget* parent);

// Names of a trial's stimuli as Sounds from the cache (already rendered by prepare()).
std::vector<Sound> sounds_of(StudyController& c, const std::vector<std::string>& names);

}  // namespace ms::gui
