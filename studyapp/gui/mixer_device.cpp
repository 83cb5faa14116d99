// MixerDevice: PlaybackMixer::render behind QIODevice::readData (pull mode of QAudioSink).
#include "studyapp/gui/mixer_device.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace ms::gui {

namespace {
constexpr std::size_t kScratchFrames = 4096;
}

MixerDevice::MixerDevice(PlaybackMixer& mixer, QAudioFormat::SampleFormat format, QObject* parent)
    : QIODevice(parent), mixer_(mixer), format_(format), scratch_(kScratchFrames) {}

qint64 MixerDevice::bytesAvailable() const {
  return (qint64{1} << 16) + QIODevice::bytesAvailable();
}

qint64 MixerDevice::readData(char* data, qint64 max_bytes) {
  if (format_ == QAudioFormat::Float) {
    const auto frames = static_cast<std::size_t>(max_bytes) / sizeof(float);
    mixer_.render(reinterpret_cast<float*>(data), frames);
    return static_cast<qint64>(frames * sizeof(float));
  }
  // Int16: render in chunks through the scratch buffer, clip, scale.
  auto* out = reinterpret_cast<std::int16_t*>(data);
  const auto frames = static_cast<std::size_t>(max_bytes) / sizeof(std::int16_t);
  for (std::size_t done = 0; done < frames;) {
    const std::size_t n = std::min(kScratchFrames, frames - done);
    mixer_.render(scratch_.data(), n);
    for (std::size_t i = 0; i < n; ++i)
      out[done + i] = static_cast<std::int16_t>(std::lround(std::clamp(scratch_[i], -1.0f, 1.0f) * 32767.0f));
    done += n;
  }
  return static_cast<qint64>(frames * sizeof(std::int16_t));
}

}  // namespace ms::gui
