// Where a trial's sounds go: the PlaybackMixer pulled by a QAudioSink on the chosen device, or the
// null output (`--audio null`, or no device), which advances the mixer in real time without sound so
// play/stop/switch behave and are logged the same way.
#pragma once
#include <QAudioDevice>
#include <QElapsedTimer>
#include <QObject>
#include <QStringList>
#include <QTimer>

#include <memory>
#include <vector>

#include "studyapp/core/playback_mixer.hpp"

class QAudioSink;

namespace ms::gui {

class MixerDevice;

class AudioOutput : public QObject {
  Q_OBJECT

 public:
  // `device`: "default", "null" or a device description (QAudioDevice::description()). A device that
  // is missing or cannot play the format leaves the output null; message() then says why.
  AudioOutput(double sample_rate_hz, const QString& device, QObject* parent = nullptr);
  ~AudioOutput() override;

  PlaybackMixer& mixer() { return mixer_; }
  bool is_null() const { return sink_ == nullptr; }
  QString device_name() const { return device_name_; }
  QString message() const { return message_; }
  double sample_rate_hz() const { return sample_rate_hz_; }

  static QStringList device_names();  // descriptions of the system's outputs

 signals:
  void playingChanged(bool playing);  // also when the mixer switched to another stimulus

 private:
  void tick();

  double sample_rate_hz_;
  PlaybackMixer mixer_;
  QString device_name_, message_;
  std::unique_ptr<MixerDevice> device_;
  std::unique_ptr<QAudioSink> sink_;
  QTimer timer_;              // null output: advances the mixer; both: watches playing()
  QElapsedTimer clock_;
  double frames_due_ = 0.0;   // null output: frames owed to the clock
  std::vector<float> scratch_;
  bool was_playing_ = false;
  int was_current_ = -1;
};

// A 1 kHz sine, 1 s at -20 dBFS with 10 ms raised-cosine ramps, for checking the output level.
Samples calibration_tone(double sample_rate_hz);

}  // namespace ms::gui
