// MUSHRA (ITU-R BS.1534): the open reference, one play button and one vertical 0-100 slider per stimulus
// of the trial (hidden reference and anchors among them, in the schedule's order), the five quality
// labels, seamless switching and looping. Next waits until every stimulus was heard.
#include <QGridLayout>
#include <QSlider>

#include "studyapp/gui/trial_view.hpp"

namespace ms::gui {

namespace {

class MushraView : public TrialView {
 public:
  MushraView(StudyController& c, QWidget* parent) : TrialView(c, parent) {
    const Trial& trial = c.session().current();
    std::vector<std::string> names{trial.reference};
    names.insert(names.end(), trial.stimuli.begin(), trial.stimuli.end());
    c.set_sounds(sounds_of(c, names));
    require_all_played_ = c.session().current_block().listen_all;
    digits_play_sounds_ = true;  // 1 = reference, 2.. = A, B, ...
    add_prompt("Rate the basic audio quality of each sound compared with the reference. "
               "Click a sound while another plays to switch at the same moment.");

    QStringList labels{"Reference"};
    auto* grid = new QGridLayout;
    const QStringList quality{"Excellent", "Good", "Fair", "Poor", "Bad"};
    auto* scale = new QVBoxLayout;
    for (const QString& q : quality) {
      auto* l = new QLabel(q, this);
      l->setObjectName("quality-" + q);
      l->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
      scale->addWidget(l, 1);
    }
    grid->addLayout(scale, 0, 0);
    for (std::size_t i = 0; i < trial.stimuli.size(); ++i) {
      const QString letter = QString(QChar('A' + static_cast<int>(i % 26)));
      labels << letter;
      auto* slider = new QSlider(Qt::Vertical, this);
      slider->setObjectName(QString("mushra-slider-%1").arg(i));
      slider->setRange(0, 100);
      slider->setValue(0);
      slider->setTickPosition(QSlider::TicksBothSides);
      slider->setTickInterval(20);
      slider->setMinimumHeight(220);
      auto* value = new QLabel("0", this);
      value->setAlignment(Qt::AlignCenter);
      connect(slider, &QSlider::valueChanged, value, [value](int v) { value->setNum(v); });
      grid->addWidget(slider, 0, static_cast<int>(i) + 1, Qt::AlignHCenter);
      grid->addWidget(value, 1, static_cast<int>(i) + 1, Qt::AlignHCenter);
      sliders_.push_back(slider);
    }
    layout_->addLayout(grid);
    add_sound_buttons(labels, true, true);
    // Line the play buttons up under their sliders.
    for (std::size_t i = 0; i < trial.stimuli.size(); ++i) {
      QPushButton* b = play_button(i + 1);
      b->parentWidget()->layout()->removeWidget(b);
      grid->addWidget(b, 2, static_cast<int>(i) + 1);
    }
    names_ = trial.stimuli;
    add_next([this] {
      nlohmann::json a = nlohmann::json::object();
      for (std::size_t i = 0; i < names_.size(); ++i) a[names_[i]] = sliders_[i]->value();
      return a;
    });
  }

 private:
  std::vector<std::string> names_;
  std::vector<QSlider*> sliders_;
};

}  // namespace

TrialView* make_mushra_view(StudyController& c, QWidget* parent) { return new MushraView(c, parent); }

}  // namespace ms::gui
