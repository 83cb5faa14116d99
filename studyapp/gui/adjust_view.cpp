// Method of adjustment: one slider per protocol slider, named by its `label` between its `low` and `high`
// end labels (the parameter's value beside it only with `show_value`), on a normalised 0-100 scale
// mapped to [min, max]. Every move re-synthesises the stimulus with the slider values as overrides on a
// worker thread (the UI never blocks; moves during a render are coalesced into one more render), and the
// new sound plays as soon as it is ready — after a key press or a click on the groove at once, after a
// drag when the slider is released — so the stored values are always ones that were heard. With a
// `target` the target stimulus is playable beside the adjusted sound. The time from a move to the new
// sound goes to the log (each play's detail, and the view's "resynth_ms" property), not to the screen.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <QElapsedTimer>
#include <QGridLayout>
#include <QSlider>

#include "studyapp/gui/async_render.hpp"
#include "studyapp/gui/trial_view.hpp"

namespace ms::gui {

namespace {

class AdjustView : public TrialView {
 public:
  AdjustView(StudyController& c, QWidget* parent) : TrialView(c, parent) {
    const auto* spec = std::get_if<AdjustBlock>(&c.block().body);
    if (spec) block_ = *spec;
    setObjectName("adjust-view");
    const bool target = block_.target.has_value();
    add_prompt(target ? "Move the sliders until your sound matches the target sound. Each change plays the new "
                        "sound; play the target as often as you like."
                      : "Move the sliders until the sound seems right to you. Each change plays the new sound.");
    auto* grid = new QGridLayout;
    int row = 0;
    for (const Slider& s : block_.sliders) {
      const QString name = s.label.empty() ? QString("Slider %1").arg(row + 1) : QString::fromStdString(s.label);
      grid->addWidget(new QLabel("<b>" + name + "</b>", body_widget()), row, 0);
      grid->addWidget(new QLabel(QString::fromStdString(s.low), body_widget()), row, 1, Qt::AlignRight);
      auto* slider = new QSlider(Qt::Horizontal, body_widget());
      slider->setObjectName(QString::fromStdString("adjust-" + s.key));
      slider->setAccessibleName(name);
      slider->setRange(0, 100);
      // Start where the parameter set puts the key (mid-range when it is not written, e.g. from a material).
      const int start = start_position(c, block_.paramset.name, s);
      slider->setValue(start);
      slider->setMinimumWidth(240);
      grid->addWidget(slider, row, 2);
      grid->addWidget(new QLabel(QString::fromStdString(s.high), body_widget()), row, 3);
      QLabel* value = nullptr;
      if (s.show_value) {
        value = new QLabel(QString::fromStdString(shown_value(to_value(s, start))), body_widget());
        value->setObjectName(QString::fromStdString("adjust-value-" + s.key));
        grid->addWidget(value, row, 4);
      }
      connect(slider, &QSlider::valueChanged, this, [this, value, s, slider](int pos) {
        if (value) value->setText(QString::fromStdString(shown_value(to_value(s, pos))));
        if (!slider->isSliderDown()) play_when_ready_ = true;  // keys, wheel, a click on the groove
        request_render();
      });
      connect(slider, &QSlider::sliderReleased, this, [this] { play_when_ready_ = true; maybe_autoplay(); });
      sliders_.push_back(slider);
      ++row;
    }
    grid->setColumnStretch(2, 1);
    layout_->addLayout(grid);
    std::vector<Sound> sounds;
    QStringList labels;
    if (target) {
      sounds.push_back(Sound{block_.target->name, c.samples(block_.target->name)});
      labels << "Target";
    }
    adjusted_ = sounds.size();
    sounds.push_back(Sound{block_.paramset.name, c.samples(block_.paramset.name)});
    labels << "Your sound";
    c.set_sounds(std::move(sounds));
    add_sound_buttons(labels, false);
    status_ = new QLabel(body_widget());
    status_->setObjectName("resynth-status");
    layout_->addWidget(status_);
    add_next([this] { return AdjustAnswer{slider_values()}; });
    if (!c.previewing()) request_render();
  }

 protected:
  bool ready() const override { return current_ok_ && !busy_; }
  QString why_incomplete() const override { return busy_ ? QString("Making the new sound...") : QString(); }

 private:
  QWidget* body_widget() const { return body(); }

  static double to_value(const Slider& s, int pos) { return s.min + (s.max - s.min) * pos / 100.0; }

  // Three significant digits (%g: plain notation unless very small or large).
  static std::string shown_value(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", v);
    return text;
  }

  static int start_position(StudyController& c, const std::string& stimulus, const Slider& s) {
    const auto v = c.previewing() ? std::nullopt : c.cache().parameter_value(stimulus, s.key);
    if (!v || s.max == s.min) return 50;
    return std::clamp(static_cast<int>(std::lround(100.0 * (*v - s.min) / (s.max - s.min))), 0, 100);
  }

  std::map<std::string, double> slider_values() const {
    std::map<std::string, double> values;
    for (std::size_t i = 0; i < sliders_.size(); ++i) values[block_.sliders[i].key] = to_value(block_.sliders[i], sliders_[i]->value());
    return values;
  }

  // What the played variant was: the slider values, its recipe hash and how long it took to make.
  std::string variant_detail(double latency_ms, double render_ms) const {
    nlohmann::json detail{{"set", slider_values()}, {"resynth_ms", latency_ms}, {"render_ms", render_ms}};
    try {
      detail["hash"] = controller_.cache().hash_with(block_.paramset.name, overrides());
    } catch (const std::exception&) {
    }
    return detail.dump();
  }

  std::vector<std::string> overrides() const {
    std::vector<std::string> o;
    for (std::size_t i = 0; i < sliders_.size(); ++i)
      o.push_back(override_text(block_.sliders[i].key, to_value(block_.sliders[i], sliders_[i]->value())));
    return o;
  }

  void request_render() {
    if (controller_.previewing()) return;
    moved_.start();
    current_ok_ = false;
    if (busy_) {
      dirty_ = true;
      return;
    }
    busy_ = true;
    dirty_ = false;
    status_->setText("Making the new sound...");
    refresh();
    render_async(controller_.cache(), block_.paramset.name, overrides(), this,
                 [this](Samples samples, double render_ms, const std::string& error) { rendered(samples, render_ms, error); });
  }

  void rendered(const Samples& samples, double render_ms, const std::string& error) {
    busy_ = false;
    if (dirty_) return request_render();  // the sliders moved meanwhile: render their latest values
    if (!error.empty()) {
      status_->setText("This setting cannot be played; please move the slider a little.");
      status_->setToolTip(QString::fromStdString(error));
      refresh();
      return;
    }
    const double latency_ms = static_cast<double>(moved_.nsecsElapsed()) * 1e-6;
    setProperty("resynth_ms", latency_ms);
    setProperty("renders", property("renders").toInt() + 1);
    status_->clear();
    controller_.replace_sound(adjusted_, Sound{block_.paramset.name, samples, variant_detail(latency_ms, render_ms)});
    current_ok_ = true;
    maybe_autoplay();
    refresh();
  }

  void maybe_autoplay() {
    if (!play_when_ready_ || !current_ok_) return;
    for (QSlider* s : sliders_)
      if (s->isSliderDown()) return;
    play_when_ready_ = false;
    controller_.play(adjusted_);
  }

  AdjustBlock block_;
  std::vector<QSlider*> sliders_;
  std::size_t adjusted_ = 0;  // index of the adjusted sound (after the target when there is one)
  QLabel* status_ = nullptr;
  QElapsedTimer moved_;
  bool busy_ = false, dirty_ = false, current_ok_ = false, play_when_ready_ = false;
};

}  // namespace

TrialView* make_adjust_view(StudyController& c, QWidget* parent) { return new AdjustView(c, parent); }

}  // namespace ms::gui
