// Graded sounds against an open reference: one play button and one vertical slider per stimulus of the
// trial (in the schedule's order, lettered A, B, ...), the five grade labels beside the scale, seamless
// switching and looping. Keys: 1 plays the reference, the letters play the lettered sounds (webMUSHRA's
// labels), 2..9 the first eight. Next waits until every sound was heard and every slider moved (an
// untouched slider is not a grade).
//   MUSHRA (ITU-R BS.1534): 0-100 quality (Excellent ... Bad), hidden reference and anchors among the sounds.
//   BS.1116: A and B, one of them the hidden reference, on the continuous impairment scale 1.0-5.0
//   (Imperceptible ... Very annoying), one decimal; the slider starts at 5.0 but shows no grade until moved.
#include <QGridLayout>
#include <QLabel>
#include <QSlider>

#include <cmath>

#include "studyapp/core/training_feedback.hpp"
#include "studyapp/gui/trial_view.hpp"

namespace ms::gui {

namespace {

// A grading scale: slider steps (integers), the grade of a step, the labels from the top down.
struct GradeScale {
  int low = 0, high = 100, start = 0, tick = 20;
  double per_step = 1.0;  // grade = step * per_step
  int decimals = 0;
  QStringList labels;
  QString prompt;
  BlockType type = BlockType::mushra;
};

GradeScale mushra_scale() {
  GradeScale g;
  g.labels = {"Excellent", "Good", "Fair", "Poor", "Bad"};
  g.prompt = "Rate the quality of each sound compared with the reference. "
             "Click another sound while one plays to switch at the same moment.";
  return g;
}

GradeScale bs1116_scale() {
  GradeScale g;
  g.low = 10;
  g.high = 50;
  g.start = 50;
  g.tick = 10;
  g.per_step = 0.1;
  g.decimals = 1;
  g.labels = {"5 Imperceptible", "4 Perceptible, not annoying", "3 Slightly annoying", "2 Annoying",
              "1 Very annoying"};
  g.prompt = "One of A and B is the reference itself. Grade how much each differs from the reference "
             "(5.0 = no difference heard).";
  g.type = BlockType::bs1116;
  return g;
}

class MushraView : public TrialView {
 public:
  MushraView(StudyController& c, QWidget* parent, GradeScale grades) : TrialView(c, parent), scale_(std::move(grades)) {
    const Trial& trial = c.trial();
    std::vector<std::string> names{trial.reference};
    names.insert(names.end(), trial.stimuli.begin(), trial.stimuli.end());
    c.set_sounds(sounds_of(c, names));
    digits_play_sounds_ = true;  // 1 = reference, 2.. = A, B, ...
    add_prompt(scale_.prompt);

    QStringList labels{"Reference"};
    auto* grid = new QGridLayout;
    grid->setHorizontalSpacing(4);
    auto* scale = new QVBoxLayout;
    for (const QString& q : scale_.labels) {
      auto* l = new QLabel(q, body());
      l->setObjectName("quality-" + q);
      l->setWordWrap(true);
      l->setMaximumWidth(150);
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
      slider->setRange(scale_.low, scale_.high);
      slider->setValue(scale_.start);
      slider->setTickPosition(QSlider::TicksBothSides);
      slider->setTickInterval(scale_.tick);
      slider->setMinimumHeight(150);
      slider->setAccessibleName("rating of sound " + letter);
      auto* value = new QLabel(QString::fromUtf8("\u2013"), body());  // no rating yet
      value->setObjectName(QString("mushra-value-%1").arg(i));
      value->setAlignment(Qt::AlignCenter);
      connect(slider, &QSlider::valueChanged, this, [this, value, i](int v) {
        value->setText(QString::number(v * scale_.per_step, 'f', scale_.decimals));
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
    add_next([this]() -> Answer {
      if (scale_.type == BlockType::bs1116) {
        Bs1116Answer a;
        for (std::size_t i = 0; i < names_.size(); ++i)
          a.grades[names_[i]] = std::round(sliders_[i]->value() * scale_.per_step * 10.0) / 10.0;
        return a;
      }
      MushraAnswer a;
      for (std::size_t i = 0; i < names_.size(); ++i) a.scores[names_[i]] = sliders_[i]->value();
      return a;
    });
  }

 protected:
  std::vector<bool> moved() const override { return moved_; }

 private:
  GradeScale scale_;
  std::vector<std::string> names_;
  std::vector<QSlider*> sliders_;
  std::vector<bool> moved_;
};

}  // namespace

TrialView* make_mushra_view(StudyController& c, QWidget* parent) { return new MushraView(c, parent, mushra_scale()); }
TrialView* make_bs1116_view(StudyController& c, QWidget* parent) { return new MushraView(c, parent, bs1116_scale()); }

}  // namespace ms::gui
