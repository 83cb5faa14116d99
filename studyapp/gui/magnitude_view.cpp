// Magnitude estimation: the reference pair (= the block's modulus value, 100 by default) is played first, then the trial's pair; the participant
// types how different the pair sounds relative to the reference pair. The field takes a decimal point or
// comma, says why a value is refused (core's read_magnitude), takes 0 where the block has identical pairs
// (on a bounded `scale`: any value from its min to its max, shown under the prompt),
// and has the keyboard focus from the start (Enter = Next).
#include <QLineEdit>
#include <QTimer>

#include "studyapp/core/magnitude_input.hpp"
#include "studyapp/gui/trial_view.hpp"

namespace ms::gui {

namespace {

class MagnitudeView : public TrialView {
 public:
  MagnitudeView(StudyController& c, QWidget* parent) : TrialView(c, parent) {
    const Trial& trial = c.trial();
    const auto* mb = std::get_if<MagnitudeBlock>(&c.block().body);
    if (mb) block_ = *mb;
    std::vector<std::string> names;
    QStringList labels;
    if (mb && mb->modulus) {
      names = {(*mb->modulus)[0].name, (*mb->modulus)[1].name};
      labels << "Reference pair 1" << "Reference pair 2";
      modulus_count_ = 2;
    }
    names.insert(names.end(), trial.stimuli.begin(), trial.stimuli.end());
    labels << "A" << "B";
    c.set_sounds(sounds_of(c, names));
    const double modulus = mb ? mb->modulus_value : 100.0;
    const QString m = QString::number(modulus, 'g', 6), half = QString::number(modulus / 2, 'g', 6),
                  twice = QString::number(modulus * 2, 'g', 6);
    add_prompt(modulus_count_ && block_.scale
                   ? QString("First listen to the reference pair: the most different pair, counted as %1. Then listen "
                             "to A and B and type how different they sound (%2 = half as different).").arg(m, half)
               : modulus_count_ ? QString("First listen to the reference pair: its difference counts as %1. Then listen to "
                                        "A and B and type how different they sound (%2 = half as different, %3 = twice "
                                        "as different).").arg(m, half, twice)
                              : QString("Listen to A and B and type how different they sound."));
    if (block_.scale)
      add_note(QString("Use the scale from %1 (identical) to %2 (as different as the reference pair).")
                   .arg(block_.scale->min, 0, 'g', 6)
                   .arg(block_.scale->max, 0, 'g', 6));
    else if (block_.identical_pairs) add_note("Type 0 if A and B sound exactly the same.");
    add_sound_buttons(labels, false);
    entry_ = new QLineEdit(body());
    entry_->setObjectName("magnitude");
    entry_->setPlaceholderText(modulus_count_ ? QString("how different? (reference pair = %1)").arg(m) : QString("how different?"));
    entry_->setMaximumWidth(entry_->fontMetrics().averageCharWidth() * 40);
    connect(entry_, &QLineEdit::textChanged, this, [this] { refresh(); });
    layout_->addWidget(entry_);
    add_next([this] { return MagnitudeAnswer{*read_magnitude(entry_->text().toStdString(), block_).value}; });
    gate_pair();
    QTimer::singleShot(0, entry_, [e = entry_] { e->setFocus(Qt::OtherFocusReason); });
  }

 protected:
  bool ready() const override { return read_magnitude(entry_->text().toStdString(), block_).value.has_value(); }
  QString why_incomplete() const override {
    return QString::fromStdString(read_magnitude(entry_->text().toStdString(), block_).problem);
  }
  void on_sound_played(int) override { gate_pair(); }

 private:
  // The pair is playable once the reference pair was heard.
  void gate_pair() {
    const bool modulus_heard = modulus_count_ == 0 || (controller_.was_played(0) && controller_.was_played(1));
    for (std::size_t i = modulus_count_; i < controller_.sounds().size(); ++i) play_button(i)->setEnabled(modulus_heard);
  }

  std::size_t modulus_count_ = 0;
  MagnitudeBlock block_;  // its rules for a typed value (zero, scale)
  QLineEdit* entry_ = nullptr;
};

}  // namespace

TrialView* make_magnitude_view(StudyController& c, QWidget* parent) { return new MagnitudeView(c, parent); }

}  // namespace ms::gui
