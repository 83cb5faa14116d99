// TrialView: the shared controls of the trial views and the factory choosing a view per block type.
#include "studyapp/gui/trial_view.hpp"

#include <QCheckBox>
#include <QShortcut>

namespace ms::gui {

TrialView::TrialView(StudyController& controller, QWidget* parent)
    : QWidget(parent), controller_(controller), layout_(new QVBoxLayout(this)) {
  connect(&controller_, &StudyController::soundPlayed, this, [this](int index) {
    on_sound_played(index);
    refresh();
  });
  connect(&controller_, &StudyController::playingChanged, this, [this] { refresh(); });
  auto* space = new QShortcut(QKeySequence(Qt::Key_Space), this);
  connect(space, &QShortcut::activated, this, [this] { play_or_stop(); });
}

QLabel* TrialView::add_prompt(const QString& text, QBoxLayout* into) {
  auto* label = new QLabel(text, this);
  label->setObjectName("prompt");
  label->setWordWrap(true);
  QFont f = label->font();
  f.setPointSizeF(f.pointSizeF() * 1.2);
  label->setFont(f);
  (into ? into : layout_)->addWidget(label);
  return label;
}

QWidget* TrialView::add_sound_buttons(const QStringList& labels, bool seamless, bool with_loop, QBoxLayout* into,
                                      bool vertical) {
  auto* box = new QWidget(this);
  QBoxLayout* row = vertical ? static_cast<QBoxLayout*>(new QVBoxLayout(box)) : new QHBoxLayout(box);
  row->setContentsMargins(0, 0, 0, 0);
  for (int i = 0; i < labels.size(); ++i) {
    auto* b = new QPushButton(QString::fromUtf8("\u25B6 ") + labels[i], box);
    b->setObjectName(QString("play-%1").arg(i));
    b->setCheckable(true);
    b->setFocusPolicy(Qt::NoFocus);
    const auto index = static_cast<std::size_t>(i);
    connect(b, &QPushButton::clicked, this, [this, index, seamless] { press_play(index, seamless); });
    row->addWidget(b);
    play_buttons_.push_back(b);
  }
  sound_labels_ = labels;
  auto* stop = new QPushButton(QString::fromUtf8("\u25A0 Stop"), box);
  stop->setObjectName("stop");
  stop->setFocusPolicy(Qt::NoFocus);
  connect(stop, &QPushButton::clicked, this, [this] { controller_.stop(); });
  row->addWidget(stop);
  if (with_loop) {
    auto* loop = new QCheckBox("Loop", box);
    loop->setObjectName("loop");
    connect(loop, &QCheckBox::toggled, this, [this](bool on) { controller_.set_loop(on); });
    row->addWidget(loop);
  }
  if (!vertical) row->addStretch();
  (into ? into : layout_)->addWidget(box);
  if (digits_play_sounds_) {
    for (int i = 0; i < labels.size() && i < 9; ++i) {
      auto* key = new QShortcut(QKeySequence(Qt::Key_1 + i), this);
      connect(key, &QShortcut::activated, this,
              [this, i, seamless] { press_play(static_cast<std::size_t>(i), seamless); });
    }
  }
  refresh();
  return box;
}

void TrialView::press_play(std::size_t index, bool seamless) {
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
  auto* box = new QWidget(this);
  auto* row = new QHBoxLayout(box);
  row->setContentsMargins(0, 0, 0, 0);
  for (int i = 0; i < labels.size(); ++i) {
    auto* b = new QPushButton(i < 9 ? QString("%1  (%2)").arg(labels[i]).arg(i + 1) : labels[i], box);
    b->setObjectName("choice-" + names[i]);
    b->setCheckable(true);
    b->setMinimumHeight(40);
    group->addButton(b, i);
    row->addWidget(b);
    if (i < 9) {
      auto* key = new QShortcut(QKeySequence(Qt::Key_1 + i), this);
      connect(key, &QShortcut::activated, b, [b] { if (b->isEnabled()) b->click(); });
    }
  }
  connect(group, &QButtonGroup::idClicked, this, [this] { refresh(); });
  (into ? into : layout_)->addWidget(box);
  return group;
}

void TrialView::add_next(std::function<nlohmann::json()> answer, const QString& text) {
  add_next_action([this, answer = std::move(answer)] {
    if (ready() && (!require_all_played_ || controller_.played_all())) controller_.submit(answer());
  }, text);
}

void TrialView::add_next_action(std::function<void()> on_next, const QString& text) {
  hint_ = new QLabel(this);
  hint_->setObjectName("hint");
  auto* row = new QHBoxLayout;
  row->addWidget(hint_, 1);
  next_ = new QPushButton(text + QString::fromUtf8("  \u23CE"), this);
  next_->setObjectName("next");
  next_->setDefault(true);
  next_->setMinimumWidth(120);
  row->addWidget(next_);
  layout_->addStretch();
  layout_->addLayout(row);
  connect(next_, &QPushButton::clicked, this, std::move(on_next));
  for (const auto key : {Qt::Key_Return, Qt::Key_Enter}) {
    auto* shortcut = new QShortcut(QKeySequence(key), this);
    connect(shortcut, &QShortcut::activated, next_, [this] { if (next_->isEnabled()) next_->click(); });
  }
  refresh();
}

void TrialView::refresh() {
  const int playing = controller_.playing_index();
  for (std::size_t i = 0; i < play_buttons_.size(); ++i) {
    play_buttons_[i]->setChecked(static_cast<int>(i) == playing);
    play_buttons_[i]->setProperty("played", controller_.was_played(i));
  }
  if (!next_) return;
  const bool listened = !require_all_played_ || controller_.played_all();
  next_->setEnabled(ready() && listened);
  if (hint_) hint_->setText(listened ? QString() : QString("Listen to every sound before answering."));
}

TrialView* make_trial_view(StudyController& c, QWidget* parent) {
  switch (c.session().current().type) {
    case BlockType::instructions: return make_instructions_view(c, parent);
    case BlockType::ab: return make_ab_view(c, parent);
    case BlockType::mushra: return make_mushra_view(c, parent);
    case BlockType::magnitude: return make_magnitude_view(c, parent);
    case BlockType::identify: return make_identify_view(c, parent);
    case BlockType::rating: return make_rating_view(c, parent);
    case BlockType::adjust: return make_adjust_view(c, parent);
    case BlockType::staircase: return make_staircase_view(c, parent);
    case BlockType::questionnaire: return make_questionnaire_view(c, parent);
    case BlockType::unknown: break;
  }
  return make_instructions_view(c, parent);  // a validated protocol has no unknown blocks
}

std::vector<Sound> sounds_of(StudyController& c, const std::vector<std::string>& names) {
  std::vector<Sound> sounds;
  for (const std::string& n : names) sounds.push_back(Sound{n, c.cache().samples(n)});
  return sounds;
}

}  // namespace ms::gui
