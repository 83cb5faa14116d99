// The base of every trial view: the task text (the block's `prompt`, else the view's wording), play
// buttons wired to the controller (space = play the next sound not yet heard / stop; each button keeps a
// mark once its sound was heard and is lit while the mixer plays it), exclusive choice buttons (keys
// 1..n), and the Next button (Enter). Whether Next may be pressed is core's answer_gate over what the
// participant did; in training blocks with `feedback: true` the first Next shows whether the answer was
// right and the second commits it. The body scrolls inside the window; hint and Next stay in sight.
#pragma once
#include <QBoxLayout>
#include <QButtonGroup>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QStringList>
#include <QWidget>

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "studyapp/core/answer_gate.hpp"
#include "studyapp/core/answers.hpp"
#include "studyapp/gui/study_controller.hpp"

namespace ms::gui {

class TrialView : public QWidget {
 public:
  TrialView(StudyController& controller, QWidget* parent);

  AnswerGate gate() const;                          // may Next be pressed now, and if not, why
  QWidget* body() const { return body_; }           // the scrolled part (everything but hint and Next)

 protected:
  // The block's `prompt` when it has one, else `fallback`; objectName "prompt".
  QLabel* add_prompt(const QString& fallback, QBoxLayout* into = nullptr);
  QLabel* add_note(const QString& text, QBoxLayout* into = nullptr);  // smaller secondary text
  // Play buttons for the controller's sounds, objectName "play-<i>". seamless: while a sound plays, another
  // button switches to it at the same position (MUSHRA). with_loop adds the loop check box.
  QWidget* add_sound_buttons(const QStringList& labels, bool seamless, bool with_loop = false,
                             QBoxLayout* into = nullptr, bool vertical = false);
  // One play button for the next sound (objectName "play-<i>", i counting the buttons made so far) and a
  // Stop button, for views that place them themselves.
  QPushButton* make_play_button(const QString& label, bool seamless, QWidget* parent);
  QPushButton* make_stop_button(QWidget* parent);
  QPushButton* play_button(std::size_t index) const { return play_buttons_.at(index); }
  void press_play(std::size_t index, bool seamless);
  // Exclusive checkable buttons (objectName "choice-<name>"), keys 1..n select.
  QButtonGroup* add_choices(const QStringList& labels, const QStringList& names, QBoxLayout* into = nullptr);
  // The Next button (objectName "next", Enter/Return) committing answer() (stored as its JSON).
  void add_next(std::function<Answer()> answer, const QString& text = "Next");
  void add_next_action(std::function<void()> on_next, const QString& text);  // the same button, own action
  // The "play in order" button (objectName "play-sequence") over the first `count` sounds, 400 ms apart.
  void add_sequence_button(const QString& text, int count);
  void stop_sequence() { sequence_next_ = 0; }      // the running sequence plays no further sound
  virtual bool sequence_playable() const { return true; }  // false while the sounds are not ready
  void refresh();                                   // re-derive Next, the hint and the play buttons
  // What the participant did, for answer_gate. By default: one heard flag per sound of the controller.
  virtual std::vector<bool> heard() const;
  virtual std::vector<bool> moved() const { return {}; }
  virtual bool ready() const { return true; }       // the widgets hold a complete answer
  virtual QString why_incomplete() const { return {}; }
  virtual void on_sound_played(int /*index*/) {}
  // Training feedback under the buttons (green when right); hidden with an empty text.
  void show_feedback(const QString& text, bool correct);
  // Shortcut on this view (active while it is shown, whatever widget inside has focus).
  void add_key(const QKeySequence& key, std::function<void()> action);

  StudyController& controller_;
  QVBoxLayout* layout_;                             // the body's layout: views add their widgets here
  QPushButton* next_ = nullptr;
  bool digits_play_sounds_ = false;                 // keys 1..n play the sounds (views without choices)
  QLabel* hint_ = nullptr;

 private:
  void play_or_stop();
  QWidget* body_;
  QScrollArea* scroll_;
  QLabel* feedback_;
  std::vector<QPushButton*> play_buttons_;
  QStringList sound_labels_;
  void play_sequence(int from);
  int sequence_next_ = 0;                           // the next sound of a running sequence (0: none runs)
  bool awaiting_continue_ = false;                  // feedback shown; the next press commits
  nlohmann::json pending_answer_;
};

// The view for the controller's current trial (by block type).
TrialView* make_trial_view(StudyController& controller, QWidget* parent);

// One factory per block type (one file each).
TrialView* make_instructions_view(StudyController& c, QWidget* parent);
TrialView* make_ab_view(StudyController& c, QWidget* parent);
TrialView* make_mushra_view(StudyController& c, QWidget* parent);
TrialView* make_bs1116_view(StudyController& c, QWidget* parent);
TrialView* make_magnitude_view(StudyController& c, QWidget* parent);
TrialView* make_identify_view(StudyController& c, QWidget* parent);
TrialView* make_rating_view(StudyController& c, QWidget* parent);
TrialView* make_adjust_view(StudyController& c, QWidget* parent);
TrialView* make_staircase_view(StudyController& c, QWidget* parent);
TrialView* make_limits_view(StudyController& c, QWidget* parent);
TrialView* make_tokens_view(StudyController& c, QWidget* parent);
TrialView* make_changepoint_view(StudyController& c, QWidget* parent);
TrialView* make_questionnaire_view(StudyController& c, QWidget* parent);

// Names of a trial's stimuli as Sounds from the cache (already rendered by prepare(); empty buffers in
// a layout preview).
std::vector<Sound> sounds_of(StudyController& c, const std::vector<std::string>& names);

// What the participant reads above the trial: the kind of task in plain words ("Same or different?"),
// never the block's id or type name.
QString task_title(const Block& block);

}  // namespace ms::gui
