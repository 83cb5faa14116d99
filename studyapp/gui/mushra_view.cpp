// MUSHRA (ITU-R BS.1534): the open reference, one play button and one vertical 0-100 slider per stimulus
// of the trial (hidden reference and anchors among them, in the schedule's order, lettered A, B, ...),
// the five quality labels beside the scale, seamless switching and looping. Keys: 1 plays the reference,
// the letters play the lettered sounds (webMUSHRA's labels), 2..9 the first eight. Next waits until every
// sound was heard and every slider moved (an untouched 0 is not a rating).
#include <QGridLayout>
#include <QSlider>

#include "studyapp/core/training_feedback.hpp"
#include "studyapp/gui/trial_view.hpp"

namespace ms::gui {

namespace {

class MushraView : public TrialView {
 public:
  MushraView(StudyController& c, QWidget* parent) : TrialView(c, parent) {
    const Trial& trial = c.trial();
    std::vector<std::string> names{trial.reference};
    names.insert(names.end(), trial.stimuli.begin(), trial.stimuli.end());
    c.set_sounds(sounds_of(c, names));
    digits_play_sounds_ = true;  // 1 = reference, 2.. = A, B, ...
    add_prompt("Rate the quality of each sound compared with the reference. "
               "Click another sound while one plays to switch at the same moment.");

    QStringList labels{"Reference"};
    auto* grid = new QGridLayout;
    grid->setHorizontalSpacing(4);
    const QStringList quality{"Excellent", "Good", "Fair", "Poor", "Bad"};
    auto* scale = new QVBoxLayout;
    for (const QString& q : quality) {
      auto* l = new QLabel(q, body());
      l->setObjectName("quality-" + q);
      l->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
      scale->addWidget(l, 1);
    }
    grid->addLayout(scale, 0, 0);
    moved_.assign(trial.stimuli.size(), false);
    for (std::size_t i = 0; i < trial.stimuli.size(); ++i) {
      const QString letter = QString::fromStdString(mushra_letter(i));
      labels << letter;
      auto* slider = new QSlider(Qt::Vertical, body());
      slider->setObjectName(QString("mushra-slider-%1").arg(i));
      slider->setRange(0, 100);
      slider->setValue(0);
      slider->setTickPosition(QSlider::TicksBothSides);
      slider->setTickInterval(20);
      slider->setMinimumHeight(150);
      slider->setAccessibleName("rating of sound " + letter);
      auto* value = new QLabel(QString::fromUtf8("\u2013"), body());  // no rating yet
      value->setObjectName(QString("mushra-value-%1").arg(i));
      value->setAlignment(Qt::AlignCenter);
      connect(slider, &QSlider::valueChanged, this, [this, value, i](int v) {
        value->setNum(v);
        moved_[i] = true;
        refresh();
      });
      grid->addWidget(slider, 0, static_cast<int>(i) + 1, Qt::AlignHCenter);
      grid->addWidget(value, 1, static_cast<int>(i) + 1, Qt::AlignHCenter);
      sliders_.push_back(slider);
      if (i < 26) add_key(QKeySequence(Qt::Key_A + static_cast<int>(i)), [this, i] { press_play(i + 1, true); });
    }
    layout_->addLayout(grid);
    add_sound_buttons(labels, true, true);
    // Line the play buttons up under their sliders.
    for (std::size_t i = 0; i < trial.stimuli.size(); ++i) {
      QPushButton* b = play_button(i + 1);
      b->parentWidget()->layout()->removeWidget(b);
      grid->addWidget(b, 2, static_cast<int>(i) + 1);
    }
    add_note(QString("Keys: 1 plays the reference, %1 play the sounds, Space stops.")
                 .arg(trial.stimuli.size() > 1 ? QString("A to ") + QString::fromStdString(mushra_letter(std::min<std::size_t>(trial.stimuli.size(), 26) - 1))
                                               : QString("A")));
    names_ = trial.stimuli;
    add_next([this] {
      MushraAnswer a;
      for (std::size_t i = 0; i < names_.size(); ++i) a.scores[names_[i]] = sliders_[i]->value();
      return a;
    });
  }

 protected:
  std::vector<bool> moved() const override { return moved_; }

 private:
  std::vector<std::string> names_;
  std::vector<QSlider*> sliders_;
  std::vector<bool> moved_;
};

}  // namespace

TrialView* make_mushra_view(StudyController& c, QWidget* parent) { return new MushraView(c, parent); }

}  // namespace ms::gui
