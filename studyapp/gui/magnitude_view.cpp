// Magnitude estimation: the modulus pair (= 100) is played first, then the trial's pair; the participant
// types how different the pair sounds as a number > 0 relative to the modulus.
#include <QDoubleValidator>
#include <QLineEdit>

#include "studyapp/gui/trial_view.hpp"

namespace ms::gui {

namespace {

class MagnitudeView : public TrialView {
 public:
  MagnitudeView(StudyController& c, QWidget* parent) : TrialView(c, parent) {
    const Trial& trial = c.session().current();
    const auto* body = std::get_if<MagnitudeBlock>(&c.session().current_block().body);
    std::vector<std::string> names;
    QStringList labels;
    if (body && body->modulus) {
      names = {(*body->modulus)[0].name, (*body->modulus)[1].name};
      labels << "Modulus 1" << "Modulus 2";
      modulus_count_ = 2;
    }
    names.insert(names.end(), trial.stimuli.begin(), trial.stimuli.end());
    labels << "A" << "B";
    c.set_sounds(sounds_of(c, names));
    require_all_played_ = c.session().current_block().listen_all;
    add_prompt(modulus_count_ ? "First listen to the modulus pair: its difference is 100. Then listen to A and B "
                                "and type how different they sound (e.g. 50 = half as different, 200 = twice)."
                              : "Listen to A and B and type how different they sound (a number above 0).");
    add_sound_buttons(labels, false);
    entry_ = new QLineEdit(this);
    entry_->setObjectName("magnitude");
    entry_->setPlaceholderText("difference (modulus = 100)");
    auto* validator = new QDoubleValidator(0.0, 1e6, 3, entry_);
    validator->setNotation(QDoubleValidator::StandardNotation);
    validator->setLocale(QLocale::c());
    entry_->setValidator(validator);
    connect(entry_, &QLineEdit::textChanged, this, [this] { refresh(); });
    layout_->addWidget(entry_);
    add_next([this] { return value(); });
    gate_pair();
  }

 protected:
  bool ready() const override { return value() > 0.0; }
  void on_sound_played(int) override { gate_pair(); }

 private:
  double value() const {
    bool ok = false;
    const double v = QLocale::c().toDouble(entry_->text(), &ok);
    return ok ? v : 0.0;
  }
  // The pair is playable once the modulus pair was heard.
  void gate_pair() {
    const bool modulus_heard = modulus_count_ == 0 || (controller_.was_played(0) && controller_.was_played(1));
    for (std::size_t i = modulus_count_; i < controller_.sounds().size(); ++i) play_button(i)->setEnabled(modulus_heard);
  }

  std::size_t modulus_count_ = 0;
  QLineEdit* entry_ = nullptr;
};

}  // namespace

TrialView* make_magnitude_view(StudyController& c, QWidget* parent) { return new MagnitudeView(c, parent); }

}  // namespace ms::gui
