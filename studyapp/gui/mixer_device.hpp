// The QIODevice a QAudioSink pulls from: each read renders the PlaybackMixer (mono, at the protocol's
// sample rate) as float or Int16 samples; silence when nothing plays, so the sink never starves.
#pragma once
#include <QAudioFormat>
#include <QIODevice>

#include <vector>

#include "studyapp/core/playback_mixer.hpp"

namespace ms::gui {

class MixerDevice : public QIODevice {
 public:
  MixerDevice(PlaybackMixer& mixer, QAudioFormat::SampleFormat format, QObject* parent = nullptr);

  bool isSequential() const override { return true; }
  qint64 bytesAvailable() const override;

 protected:
  qint64 readData(char* data, qint64 max_bytes) override;
  qint64 writeData(const char*, qint64) override { return -1; }

 private:
  PlaybackMixer& mixer_;
  QAudioFormat::SampleFormat format_;
  std::vector<float> scratch_;  // Int16 conversion buffer, allocated once (the audio thread never allocates)
};

}  // namespace ms::gui
