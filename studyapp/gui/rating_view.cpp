// Rating: one k-point radio scale per attribute with its labelled ends. Next waits until the sound was
// heard and every attribute rated; keys 1..k rate the first attribute still open.
#include <QGridLayout>
#include <QRadioButton>
#include <QShortcut>

#include "studyapp/gui/trial_view.hpp"

namespace ms::gui {

namespace {

class RatingView : public TrialView {
 public:
  RatingView(StudyController& c, QWidget* parent) : TrialView(c, parent) {
    const auto* spec = std::get_if<RatingBlock>(&c.block().body);
    c.set_sounds(sounds_of(c, c.trial().stimuli));
    add_prompt("Listen to the sound and rate it on each scale.");
    add_sound_buttons({"Sound"}, false);
    auto* grid = new QGridLayout;
    int row = 0, max_points = 0;
    for (const RatingAttribute& a : spec ? spec->attributes : std::vector<RatingAttribute>{}) {
      const QString name = QString::fromStdString(a.name);
      grid->addWidget(new QLabel("<b>" + name + "</b>", body()), row, 0);
      grid->addWidget(new QLabel(QString::fromStdString(a.low), body()), row, 1, Qt::AlignRight);
      auto* group = new QButtonGroup(this);
      for (int k = 1; k <= a.points; ++k) {
        auto* r = new QRadioButton(QString::number(k), body());
        r->setObjectName(QString("rating-%1-%2").arg(name).arg(k));
        group->addButton(r, k);
        grid->addWidget(r, row, 1 + k);
      }
      grid->addWidget(new QLabel(QString::fromStdString(a.high), body()), row, 2 + a.points);
      connect(group, &QButtonGroup::idClicked, this, [this] { refresh(); });
      scales_.push_back({a.name, group});
      max_points = std::max(max_points, a.points);
      ++row;
    }
    grid->setColumnStretch(3 + max_points, 1);  // the end labels stay beside their scale on wide windows
    layout_->addLayout(grid);
    for (int k = 1; k <= std::min(max_points, 9); ++k) {
      auto* key = new QShortcut(QKeySequence(Qt::Key_0 + k), this);
      connect(key, &QShortcut::activated, this, [this, k] { rate_next_open(k); });
    }
    add_next([this] {
      RatingAnswer a;
      for (const auto& [name, group] : scales_) a.points[name] = group->checkedId();
      return a;
    });
  }

 protected:
  bool ready() const override {
    for (const auto& scale : scales_)
      if (!scale.second->checkedButton()) return false;
    return true;
  }

 private:
  void rate_next_open(int k) {
    for (const auto& scale : scales_)
      if (!scale.second->checkedButton()) {
        if (QAbstractButton* b = scale.second->button(k)) b->click();
        return;
      }
  }

  std::vector<std::pair<std::string, QButtonGroup*>> scales_;
};

}  // namespace

TrialView* make_rating_view(StudyController& c, QWidget* parent) { return new RatingView(c, parent); }

}  // namespace ms::gui
