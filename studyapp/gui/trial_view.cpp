// TrialView: the shared controls of the trial views and the factory choosing a view per block type.
#include "studyapp/gui/trial_view.hpp"

#include <QCheckBox>
#include <QShortcut>
#include <QTimer>

#include "studyapp/core/training_feedback.hpp"

namespace ms::gui {

namespace {

// Lines longer than about 80 characters are hard to read; wide screens get margins instead.
int readable_width(const QWidget* w) { return w->fontMetrics().averageCharWidth() * 80; }

}  // namespace

TrialView::TrialView(StudyController& controller, QWidget* parent)
    : QWidget(parent), controller_(controller) {
  auto* outer = new QVBoxLayout(this);
  outer->setContentsMargins(0, 0, 0, 0);
  scroll_ = new QScrollArea(this);
  scroll_->setObjectName("trialScroll");
  scroll_->setWidgetResizable(true);
  scroll_->setFrameShape(QFrame::NoFrame);
  auto* holder = new QWidget(scroll_);
  auto* centre = new QHBoxLayout(holder);
  centre->setContentsMargins(0, 0, 0, 0);
  body_ = new QWidget(holder);
  body_->setObjectName("trialBody");
  body_->setMaximumWidth(readable_width(this) * 3 / 2);
  layout_ = new QVBoxLayout(body_);
  layout_->setContentsMargins(4, 4, 4, 4);
  centre->addStretch(0);
  centre->addWidget(body_, 1);
  centre->addStretch(0);
  scroll_->setWidget(holder);
  outer->addWidget(scroll_, 1);
  feedback_ = new QLabel(this);
  feedback_->setObjectName("feedback");
  feedback_->setWordWrap(true);
  feedback_->hide();
  outer->addWidget(feedback_);

  connect(&controller_, &StudyController::soundPlayed, this, [this](int index) {
    on_sound_played(index);
    refresh();
  });
  connect(&controller_, &StudyController::playingChanged, this, [this] { refresh(); });
  add_key(QKeySequence(Qt::Key_Space), [this] { play_or_stop(); });
}

void TrialView::add_key(const QKeySequence& key, std::function<void()> action) {
  auto* shortcut = new QShortcut(key, this);
  connect(shortcut, &QShortcut::activated, this, std::move(action));
}

QLabel* TrialView::add_prompt(const QString& fallback, QBoxLayout* into) {
  const std::string& written = controller_.block().prompt;
  auto* label = new QLabel(written.empty() ? fallback : QString::fromStdString(written), body_);
  label->setObjectName("prompt");
  label->setWordWrap(true);
  label->setMaximumWidth(readable_width(this));
  QFont f = label->font();
  f.setPointSizeF(f.pointSizeF() * 1.2);
  label->setFont(f);
  (into ? into : layout_)->addWidget(label);
  return label;
}

QLabel* TrialView::add_note(const QString& text, QBoxLayout* into) {
  auto* label = new QLabel(text, body_);
  label->setWordWrap(true);
  label->setMaximumWidth(readable_width(this));
  label->setStyleSheet("color: palette(dark)");
  (into ? into : layout_)->addWidget(label);
  return label;
}

QWidget* TrialView::add_sound_buttons(const QStringList& labels, bool seamless, bool with_loop, QBoxLayout* into,
                                      bool vertical) {
  auto* box = new QWidget(body_);
  QBoxLayout* row = vertical ? static_cast<QBoxLayout*>(new QVBoxLayout(box)) : new QHBoxLayout(box);
  row->setContentsMargins(0, 0, 0, 0);
  for (int i = 0; i < labels.size(); ++i) row->addWidget(make_play_button(labels[i], seamless, box));
  row->addWidget(make_stop_button(box));
  if (with_loop) {
    auto* loop = new QCheckBox("Loop", box);
    loop->setObjectName("loop");
    loop->setFocusPolicy(Qt::NoFocus);
    connect(loop, &QCheckBox::toggled, this, [this](bool on) { controller_.set_loop(on); });
    row->addWidget(loop);
  }
  if (!vertical) row->addStretch();
  (into ? into : layout_)->addWidget(box);
  refresh();
  return box;
}

QPushButton* TrialView::make_play_button(const QString& label, bool seamless, QWidget* parent) {
  const std::size_t index = play_buttons_.size();
  auto* b = new QPushButton(parent);
  b->setObjectName(QString("play-%1").arg(index));
  b->setCheckable(true);
  b->setFocusPolicy(Qt::NoFocus);
  b->setMinimumWidth(b->fontMetrics().horizontalAdvance(QString::fromUtf8("\u25B6 ") + label + " \u2713") + 16);
  connect(b, &QPushButton::clicked, this, [this, index, seamless] { press_play(index, seamless); });
  play_buttons_.push_back(b);
  sound_labels_ << label;
  if (digits_play_sounds_ && index < 9)
    add_key(QKeySequence(Qt::Key_1 + int(index)), [this, index, seamless] { press_play(index, seamless); });
  return b;
}

QPushButton* TrialView::make_stop_button(QWidget* parent) {
  auto* stop = new QPushButton(QString::fromUtf8("\u25A0 Stop"), parent);
  stop->setObjectName("stop");
  stop->setFocusPolicy(Qt::NoFocus);
  connect(stop, &QPushButton::clicked, this, [this] { controller_.stop(); });
  return stop;
}

void TrialView::press_play(std::size_t index, bool seamless) {
  if (index >= play_buttons_.size() || !play_buttons_[index]->isEnabled()) return refresh();
  if (controller_.playing_index() == static_cast<int>(index)) controller_.stop();
  else if (seamless && controller_.playing()) controller_.switch_to(index);
  else controller_.play(index);
  refresh();
}

void TrialView::play_or_stop() {
  if (controller_.playing()) return controller_.stop();
  for (std::size_t i = 0; i < play_buttons_.size(); ++i)
    if (play_buttons_[i]->isEnabled() && !controller_.was_played(i)) return controller_.play(i);
  if (!play_buttons_.empty() && play_buttons_[0]->isEnabled()) controller_.play(0);
}

QButtonGroup* TrialView::add_choices(const QStringList& labels, const QStringList& names, QBoxLayout* into) {
  auto* group = new QButtonGroup(this);
  group->setExclusive(true);
  auto* box = new QWidget(body_);
  auto* row = new QHBoxLayout(box);
  row->setContentsMargins(0, 0, 0, 0);
  for (int i = 0; i < labels.size(); ++i) {
    auto* b = new QPushButton(i < 9 ? QString("%1  (%2)").arg(labels[i]).arg(i + 1) : labels[i], box);
    b->setObjectName("choice-" + names[i]);
    b->setCheckable(true);
    b->setMinimumHeight(40);
    group->addButton(b, i);
    row->addWidget(b);
    if (i < 9) add_key(QKeySequence(Qt::Key_1 + i), [b] { if (b->isEnabled()) b->click(); });
  }
  connect(group, &QButtonGroup::idClicked, this, [this] { refresh(); });
  (into ? into : layout_)->addWidget(box);
  return group;
}

void TrialView::add_next(std::function<Answer()> answer, const QString& text) {
  add_next_action([this, answer = std::move(answer)] {
    if (awaiting_continue_) {
      controller_.submit(pending_answer_);
      return;
    }
    if (!gate().may_send) return;
    nlohmann::json value = answer();  // the typed answer's stored JSON
    const Block& block = controller_.block();
    if (block.feedback && controller_.has_session()) {
      if (const auto f = training_feedback(controller_.protocol(), block, controller_.trial(), value)) {
        controller_.hold_reaction_time();  // the time to answer, not to read the feedback
        controller_.stop();
        pending_answer_ = std::move(value);
        awaiting_continue_ = true;
        body_->setEnabled(false);
        show_feedback(QString::fromStdString(f->message), f->correct);
        next_->setText(QString::fromUtf8("Continue  \u23CE"));
        refresh();
        return;
      }
    }
    controller_.submit(value);
  }, text);
}

void TrialView::add_next_action(std::function<void()> on_next, const QString& text) {
  hint_ = new QLabel(this);
  hint_->setObjectName("hint");
  hint_->setWordWrap(true);
  hint_->setStyleSheet("color: #7a4a00");
  auto* row = new QHBoxLayout;
  row->setContentsMargins(4, 0, 4, 4);
  row->addWidget(hint_, 1);
  next_ = new QPushButton(text + QString::fromUtf8("  \u23CE"), this);
  next_->setObjectName("next");
  next_->setDefault(true);
  next_->setMinimumWidth(120);
  next_->setMinimumHeight(36);
  row->addWidget(next_);
  layout_->addStretch();
  static_cast<QVBoxLayout*>(this->layout())->addLayout(row);
  connect(next_, &QPushButton::clicked, this, std::move(on_next));
  for (const auto key : {Qt::Key_Return, Qt::Key_Enter})
    add_key(QKeySequence(key), [this] { if (next_->isEnabled()) next_->click(); });
  refresh();
}

void TrialView::add_sequence_button(const QString& text, int count) {
  auto* sequence = new QPushButton(text, body_);
  sequence->setObjectName("play-sequence");
  connect(sequence, &QPushButton::clicked, this, [this] { play_sequence(0); });
  layout_->addWidget(sequence);
  connect(&controller_, &StudyController::playingChanged, this, [this, count](bool playing) {
    if (!playing && sequence_next_ > 0 && sequence_next_ < count)
      QTimer::singleShot(400, this, [this] { play_sequence(sequence_next_); });
  });
}

void TrialView::play_sequence(int from) {
  if (!sequence_playable()) return;
  sequence_next_ = from + 1;
  controller_.play(static_cast<std::size_t>(from));
}

void TrialView::show_feedback(const QString& text, bool correct) {
  feedback_->setText(text);
  feedback_->setStyleSheet(correct ? "color: #1b6e20; font-weight: bold; padding: 4px"
                                   : "color: #a02000; font-weight: bold; padding: 4px");
  feedback_->setVisible(!text.isEmpty());
}

std::vector<bool> TrialView::heard() const {
  std::vector<bool> out;
  for (std::size_t i = 0; i < play_buttons_.size(); ++i) out.push_back(controller_.was_played(i));
  return out;
}

AnswerGate TrialView::gate() const {
  if (awaiting_continue_) return {true, ""};
  if (!controller_.has_trial()) return {false, ""};  // a view left over after the last answer
  TrialInputs in;
  in.heard = heard();
  in.moved = moved();
  in.complete = ready();
  in.why_incomplete = why_incomplete().toStdString();
  return answer_gate(controller_.block(), in);
}

void TrialView::refresh() {
  if (!controller_.has_trial()) return;
  const int playing = controller_.playing_index();
  for (std::size_t i = 0; i < play_buttons_.size(); ++i) {
    const bool heard_it = controller_.was_played(i);
    play_buttons_[i]->setChecked(static_cast<int>(i) == playing);
    play_buttons_[i]->setProperty("played", heard_it);
    play_buttons_[i]->setText(QString::fromUtf8("\u25B6 ") + sound_labels_.value(static_cast<int>(i)) +
                              (heard_it ? QString::fromUtf8(" \u2713") : QString()));
    play_buttons_[i]->setToolTip(heard_it ? "heard" : "not heard yet");
  }
  if (!next_) return;
  const AnswerGate g = gate();
  next_->setEnabled(g.may_send);
  if (hint_) hint_->setText(QString::fromStdString(g.missing));
}

TrialView* make_trial_view(StudyController& c, QWidget* parent) {
  switch (c.trial().type) {
    case BlockType::instructions: return make_instructions_view(c, parent);
    case BlockType::ab: return make_ab_view(c, parent);
    case BlockType::mushra: return make_mushra_view(c, parent);
    case BlockType::magnitude: return make_magnitude_view(c, parent);
    case BlockType::identify: return make_identify_view(c, parent);
    case BlockType::rating: return make_rating_view(c, parent);
    case BlockType::adjust: return make_adjust_view(c, parent);
    case BlockType::staircase: return make_staircase_view(c, parent);
    case BlockType::questionnaire: return make_questionnaire_view(c, parent);
    case BlockType::bs1116: return make_bs1116_view(c, parent);
    case BlockType::limits: return make_limits_view(c, parent);
    case BlockType::tokens: return make_tokens_view(c, parent);
    case BlockType::changepoint: return make_changepoint_view(c, parent);
    case BlockType::unknown: break;
  }
  return make_instructions_view(c, parent);  // a validated protocol has no unknown blocks
}

std::vector<Sound> sounds_of(StudyController& c, const std::vector<std::string>& names) {
  std::vector<Sound> sounds;
  for (const std::string& n : names) sounds.push_back(Sound{n, c.samples(n)});
  return sounds;
}

QString task_title(const Block& block) {
  switch (block.type) {
    case BlockType::instructions: return "Instructions";
    case BlockType::ab:
      switch (std::get<AbBlock>(block.body).mode) {
        case AbMode::same_different: return "Same or different?";
        case AbMode::preference: return "Which do you prefer?";
        case AbMode::abx: return "Which one is X?";
        case AbMode::two_afc: return "Find the odd sound";
        case AbMode::bipolar: return "Compare two sounds";
      }
      break;
    case BlockType::mushra: return "Rate the sound quality";
    case BlockType::magnitude: return "How different?";
    case BlockType::identify: return "What do you hear?";
    case BlockType::rating: return "Describe the sound";
    case BlockType::adjust: return "Adjust the sound";
    case BlockType::staircase: return "Spot the difference";
    case BlockType::questionnaire: return "A few questions";
    case BlockType::bs1116: return "Grade the difference";
    case BlockType::limits: return "Do you hear a change?";
    case BlockType::tokens: return "Same or different?";
    case BlockType::changepoint: return "Where does the material change?";
    case BlockType::unknown: break;
  }
  return "Listening test";
}

}  // namespace ms::gui
