// A/B trials: same/different, preference, ABX ("X is A / X is B"), 2AFC, and the bipolar -3..+3 comparison
// of B with A (seven radio buttons) — against the pair's reference when the protocol gives one ([A, B, REF]:
// the reference is played after A and B, and +3 means B is much closer to it). Answers are answers.hpp's.
#include <QRadioButton>

#include "studyapp/gui/trial_view.hpp"

namespace ms::gui {

namespace {

class AbView : public TrialView {
 public:
  AbView(StudyController& c, QWidget* parent) : TrialView(c, parent) {
    const Trial& trial = c.trial();
    const auto* spec = std::get_if<AbBlock>(&c.block().body);
    mode_ = spec ? spec->mode : AbMode::same_different;
    c.set_sounds(sounds_of(c, trial.stimuli));
    QStringList labels{"A", "B"};
    const bool with_reference = mode_ != AbMode::abx && trial.stimuli.size() > 2;
    if (trial.stimuli.size() > 2) labels << (with_reference ? "Reference" : "X");
    switch (mode_) {
      case AbMode::same_different: add_prompt("Are A and B the same or different?"); break;
      case AbMode::preference: add_prompt("Which sound do you prefer?"); break;
      case AbMode::abx: add_prompt("Is X the same as A or the same as B?"); break;
      case AbMode::two_afc: add_prompt("Which of the two sounds is the different one (the target)?"); break;
      case AbMode::bipolar:
        add_prompt(with_reference ? "Which of A and B is closer to the reference? (-3: A much closer ... +3: B much closer)"
                                  : "Compared with A, how is B? (-3 much worse ... +3 much better)");
        break;
    }
    if (with_reference && mode_ != AbMode::bipolar) add_note("The reference plays after A and B.");
    add_sound_buttons(labels, false);
    if (mode_ == AbMode::bipolar) {
      // Keys 1..7 choose -3..+3 (the number under each point).
      auto* row = new QHBoxLayout;
      row->addWidget(new QLabel(with_reference ? "A much closer" : "much worse", body()));
      bipolar_ = new QButtonGroup(this);
      for (int v = -3; v <= 3; ++v) {
        auto* r = new QRadioButton(v > 0 ? QString("+%1").arg(v) : QString::number(v), body());
        r->setToolTip(QString("key %1").arg(v + 4));
        r->setObjectName(QString("bipolar-%1").arg(v));
        bipolar_->addButton(r, v);
        row->addWidget(r);
        add_key(QKeySequence(Qt::Key_1 + v + 3), [r] { r->click(); });
      }
      row->addWidget(new QLabel(with_reference ? "B much closer" : "much better", body()));
      row->addStretch();
      connect(bipolar_, &QButtonGroup::idClicked, this, [this] { refresh(); });
      layout_->addLayout(row);
      add_note("Keys 1 to 7 choose the points from left to right.");
    } else if (mode_ == AbMode::same_different) {
      choices_ = add_choices({"Same", "Different"}, {"same", "different"});
    } else if (mode_ == AbMode::abx) {
      choices_ = add_choices({"X is A", "X is B"}, {"A", "B"});
    } else {
      choices_ = add_choices({"A", "B"}, {"A", "B"});
    }
    add_next([this] { return answer(); });
  }

 protected:
  bool ready() const override {
    return mode_ == AbMode::bipolar ? bipolar_->checkedButton() != nullptr : choices_->checkedId() >= 0;
  }

 private:
  Answer answer() const {
    if (mode_ == AbMode::bipolar) return BipolarAnswer{bipolar_->checkedId()};
    const int id = choices_->checkedId();
    if (mode_ == AbMode::same_different) return SameDifferentAnswer{id == 1};
    return ChoiceAnswer{id == 0 ? AbInterval::a : AbInterval::b};
  }

  AbMode mode_;
  QButtonGroup* choices_ = nullptr;
  QButtonGroup* bipolar_ = nullptr;
};

}  // namespace

TrialView* make_ab_view(StudyController& c, QWidget* parent) { return new AbView(c, parent); }

}  // namespace ms::gui
