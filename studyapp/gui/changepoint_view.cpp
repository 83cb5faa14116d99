// Change-point judgement over one sweep (Skandalou & Ireland 2017, Exp. 3): the sweep's sounds in their
// fixed order, one play button each and, from the second sound on, a "the material changed here" toggle
// beside it; a button plays the whole sweep in order. A sound's toggle works once the sound was heard,
// and Next waits until every sound was heard (answer_gate); no mark at all is an answer too. The swept
// values are not shown.
#include <QGridLayout>

#include "studyapp/gui/trial_view.hpp"

namespace ms::gui {

namespace {

class ChangepointView : public TrialView {
 public:
  ChangepointView(StudyController& c, QWidget* parent) : TrialView(c, parent) {
    setObjectName("changepoint-view");
    const std::vector<std::string>& names = c.trial().stimuli;
    c.set_sounds(sounds_of(c, names));
    add_prompt("The sounds are one object whose material changes little by little. Listen to them in order and "
               "mark each sound at which, in your opinion, the material changed (any number, or none).");
    add_sequence_button(QString::fromUtf8("\u25B6 Play all in order"), int(names.size()));
    // Per sound its play button, then (from the second sound on) its mark; in order down one column, or
    // down three for a long sweep (19 sounds fit a 1024x600 screen without scrolling).
    const std::size_t columns = names.size() > 12 ? 3 : 1;
    const std::size_t rows = (names.size() + columns - 1) / columns;
    auto* sweep = new QWidget(body());
    auto* grid = new QGridLayout(sweep);
    grid->setContentsMargins(0, 0, 0, 0);
    grid->setHorizontalSpacing(6);
    for (std::size_t i = 0; i < names.size(); ++i) {
      const int row = int(i % rows), column = 2 * int(i / rows);
      grid->addWidget(make_play_button(QString("Sound %1").arg(i + 1), false, sweep), row, column);
      auto* mark = new QPushButton(QString("Changed here"), sweep);
      mark->setObjectName(QString("mark-%1").arg(i));
      mark->setCheckable(true);
      mark->setFocusPolicy(Qt::NoFocus);
      mark->setStyleSheet("QPushButton:checked { background-color: #24466e; color: white; }");  // as the browser's
      mark->setEnabled(false);
      mark->setVisible(i > 0);  // nothing comes before the first sound
      grid->addWidget(mark, row, column + 1);
      marks_.push_back(mark);
    }
    grid->setColumnStretch(int(2 * columns), 1);
    grid->addWidget(make_stop_button(sweep), int(rows), 0);
    layout_->addWidget(sweep);
    add_next([this] {
      ChangepointAnswer a;
      for (std::size_t i = 1; i < marks_.size(); ++i)
        if (marks_[i]->isChecked()) a.marks.push_back(i);
      return a;
    });
  }

 protected:
  void on_sound_played(int index) override {
    if (index > 0 && std::size_t(index) < marks_.size()) marks_[std::size_t(index)]->setEnabled(true);
  }

 private:
  std::vector<QPushButton*> marks_;
};

}  // namespace

TrialView* make_changepoint_view(StudyController& c, QWidget* parent) { return new ChangepointView(c, parent); }

}  // namespace ms::gui
