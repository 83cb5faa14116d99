// AudioOutput: QAudioSink (float or Int16, mono) in pull mode, or the real-time null output.
#include "studyapp/gui/audio_output.hpp"

#include <QAudioSink>
#include <QMediaDevices>

#include <cmath>
#include <numbers>

#include "studyapp/gui/mixer_device.hpp"

namespace ms::gui {

namespace {

QAudioFormat mono_format(double sample_rate_hz, QAudioFormat::SampleFormat sample_format) {
  QAudioFormat f;
  f.setSampleRate(static_cast<int>(std::lround(sample_rate_hz)));
  f.setChannelCount(1);
  f.setSampleFormat(sample_format);
  return f;
}

constexpr int kTickMs = 10;

}  // namespace

AudioOutput::AudioOutput(double sample_rate_hz, const QString& device, QObject* parent)
    : QObject(parent), sample_rate_hz_(sample_rate_hz), mixer_(sample_rate_hz), scratch_(8192) {
  QAudioDevice chosen;
  if (device == "null") {
    device_name_ = "null";
  } else if (device.isEmpty() || device == "default") {
    chosen = QMediaDevices::defaultAudioOutput();
    if (chosen.isNull())
      message_ = "No audio output device was found: sounds will not be heard (null output); plays are still logged.";
  } else {
    for (const QAudioDevice& d : QMediaDevices::audioOutputs())
      if (d.description() == device) chosen = d;
    if (chosen.isNull())
      message_ = QString("Audio device '%1' was not found (available: %2); using the null output.")
                     .arg(device, device_names().isEmpty() ? QString("none") : device_names().join(", "));
  }
  if (!chosen.isNull()) {
    for (const auto sample_format : {QAudioFormat::Float, QAudioFormat::Int16}) {
      const QAudioFormat format = mono_format(sample_rate_hz, sample_format);
      if (!chosen.isFormatSupported(format)) continue;
      device_ = std::make_unique<MixerDevice>(mixer_, sample_format);
      device_->open(QIODevice::ReadOnly);
      sink_ = std::make_unique<QAudioSink>(chosen, format);
      sink_->setBufferSize(static_cast<qsizetype>(sample_rate_hz * 0.04) * format.bytesPerFrame());  // ~40 ms
      sink_->start(device_.get());
      device_name_ = chosen.description();
      break;
    }
    if (!sink_)
      message_ = QString("Audio device '%1' cannot play mono sound at %2 Hz; using the null output.")
                     .arg(chosen.description())
                     .arg(sample_rate_hz);
  }
  if (!sink_ && device_name_.isEmpty()) device_name_ = "null";
  clock_.start();
  connect(&timer_, &QTimer::timeout, this, &AudioOutput::tick);
  timer_.start(kTickMs);
}

AudioOutput::~AudioOutput() {
  if (sink_) sink_->stop();  // the audio thread stops pulling before the mixer goes away
  sink_.reset();
  device_.reset();
}

void AudioOutput::tick() {
  if (!sink_) {
    // The null output consumes the mixer at the sample rate, like a sound card would.
    frames_due_ += static_cast<double>(clock_.restart()) * 1e-3 * sample_rate_hz_;
    while (frames_due_ >= 1.0) {
      const auto n = std::min(scratch_.size(), static_cast<std::size_t>(frames_due_));
      mixer_.render(scratch_.data(), n);
      frames_due_ -= static_cast<double>(n);
    }
  }
  // The mixer applies commands at its next render: its state, not the last click, is what is heard.
  const bool playing = mixer_.playing();
  const int current = mixer_.current();
  if (playing != was_playing_ || (playing && current != was_current_)) {
    was_playing_ = playing;
    was_current_ = current;
    emit playingChanged(playing);
  }
}

QStringList AudioOutput::device_names() {
  QStringList names;
  for (const QAudioDevice& d : QMediaDevices::audioOutputs()) names << d.description();
  return names;
}

Samples calibration_tone(double sample_rate_hz) {
  const auto n = static_cast<std::size_t>(sample_rate_hz);
  const auto ramp = static_cast<std::size_t>(0.010 * sample_rate_hz);
  const double amplitude = std::pow(10.0, -20.0 / 20.0);
  std::vector<float> tone(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t_s = static_cast<double>(i) / sample_rate_hz;
    double gain = 1.0;
    const std::size_t edge = std::min(i, n - 1 - i);
    if (edge < ramp) gain = 0.5 - 0.5 * std::cos(std::numbers::pi * static_cast<double>(edge) / static_cast<double>(ramp));
    tone[i] = static_cast<float>(amplitude * gain * std::sin(2.0 * std::numbers::pi * 1000.0 * t_s));
  }
  return std::make_shared<const std::vector<float>>(std::move(tone));
}

}  // namespace ms::gui
