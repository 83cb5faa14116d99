// Method of adjustment: one slider per protocol slider on a normalised 0-100 scale mapped to [min, max];
// every move re-synthesises the stimulus with the slider values as overrides on a worker thread (the UI
// never blocks; moves during a render are coalesced into one more render), and the new sound plays when
// the slider is released. The time from a move to the new sound is shown and kept in the view's
// "resynth_ms" property; plays and time are stored with the answer.
#include <algorithm>
#include <cmath>
#include <QCheckBox>
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
    const auto* body = std::get_if<AdjustBlock>(&c.session().current_block().body);
    if (body) block_ = *body;
    setObjectName("adjust-view");
    add_prompt("Move the sliders until the sound matches what you are asked for; the sound is re-made as you move.");
    auto* grid = new QGridLayout;
    int row = 0;
    for (const Slider& s : block_.sliders) {
      grid->addWidget(new QLabel(QString::fromStdString(s.key), this), row, 0);
      auto* slider = new QSlider(Qt::Horizontal, this);
      slider->setObjectName(QString::fromStdString("adjust-" + s.key));
      slider->setRange(0, 100);
      // Start where the parameter set puts the key (mid-range when it is not written, e.g. from a material).
      const int start = start_position(c.cache(), block_.paramset.name, s);
      slider->setValue(start);
      slider->setMinimumWidth(320);
      grid->addWidget(slider, row, 1);
      auto* value = new QLabel(this);
      grid->addWidget(value, row, 2);
      connect(slider, &QSlider::valueChanged, this, [this, value, s](int pos) {
        value->setText(QString::number(to_value(s, pos), 'g', 4));
        request_render();
      });
      connect(slider, &QSlider::sliderReleased, this, [this] { play_when_ready_ = true; maybe_autoplay(); });
      value->setText(QString::number(to_value(s, start), 'g', 4));
      sliders_.push_back(slider);
      ++row;
    }
    layout_->addLayout(grid);
    c.set_sounds({Sound{block_.paramset.name, c.cache().samples(block_.paramset.name)}});
    add_sound_buttons({"Sound"}, false);
    status_ = new QLabel("rendering...", this);
    status_->setObjectName("resynth-status");
    layout_->addWidget(status_);
    add_next([this] {
      nlohmann::json a = nlohmann::json::object();
      for (std::size_t i = 0; i < sliders_.size(); ++i) a[block_.sliders[i].key] = to_value(block_.sliders[i], sliders_[i]->value());
      return a;
    });
    request_render();
  }

 protected:
  bool ready() const override { return current_ok_ && !busy_; }

 private:
  static double to_value(const Slider& s, int pos) { return s.min + (s.max - s.min) * pos / 100.0; }

  static int start_position(const StimulusCache& cache, const std::string& stimulus, const Slider& s) {
    const auto v = cache.parameter_value(stimulus, s.key);
    if (!v || s.max == s.min) return 50;
    return std::clamp(static_cast<int>(std::lround(100.0 * (*v - s.min) / (s.max - s.min))), 0, 100);
  }

  // What the played variant was: the slider values and its recipe hash (logged with each play).
  std::string variant_detail() const {
    nlohmann::json d = nlohmann::json::object();
    for (std::size_t i = 0; i < sliders_.size(); ++i) d[block_.sliders[i].key] = to_value(block_.sliders[i], sliders_[i]->value());
    try {
      return nlohmann::json{{"set", d}, {"hash", controller_.cache().hash_with(block_.paramset.name, overrides())}}.dump();
    } catch (const std::exception&) {
      return nlohmann::json{{"set", d}}.dump();
    }
  }

  std::vector<std::string> overrides() const {
    std::vector<std::string> o;
    for (std::size_t i = 0; i < sliders_.size(); ++i)
      o.push_back(override_text(block_.sliders[i].key, to_value(block_.sliders[i], sliders_[i]->value())));
    return o;
  }

  void request_render() {
    moved_.start();
    current_ok_ = false;
    if (busy_) {
      dirty_ = true;
      return;
    }
    busy_ = true;
    dirty_ = false;
    refresh();
    render_async(controller_.cache(), block_.paramset.name, overrides(), this,
                 [this](Samples samples, double render_ms, const std::string& error) { rendered(samples, render_ms, error); });
  }

  void rendered(const Samples& samples, double render_ms, const std::string& error) {
    busy_ = false;
    if (dirty_) return request_render();  // the sliders moved meanwhile: render their latest values
    if (!error.empty()) {
      status_->setText(QString::fromStdString("cannot re-synthesise: " + error));
      refresh();
      return;
    }
    const double latency_ms = static_cast<double>(moved_.nsecsElapsed()) * 1e-6;
    setProperty("resynth_ms", latency_ms);
    setProperty("renders", property("renders").toInt() + 1);
    status_->setText(QString("re-synthesised in %1 ms (render %2 ms)").arg(latency_ms, 0, 'f', 1).arg(render_ms, 0, 'f', 1));
    controller_.replace_sound(0, Sound{block_.paramset.name, samples, variant_detail()});
    current_ok_ = true;
    maybe_autoplay();
    refresh();
  }

  void maybe_autoplay() {
    if (!play_when_ready_ || !current_ok_) return;
    for (QSlider* s : sliders_)
      if (s->isSliderDown()) return;
    play_when_ready_ = false;
    controller_.play(0);
  }

  AdjustBlock block_;
  std::vector<QSlider*> sliders_;
  QLabel* status_ = nullptr;
  QElapsedTimer moved_;
  bool busy_ = false, dirty_ = false, current_ok_ = false, play_when_ready_ = false;
};

}  // namespace

TrialView* make_adjust_view(StudyController& c, QWidget* parent) { return new AdjustView(c, parent); }

}  // namespace ms::gui
