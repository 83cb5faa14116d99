// PlaybackMixer: commands are atomics read at the start of each render() call; a switch fades the old
// stimulus out and the new one in over the same frames (equal-gain linear crossfade of correlated
// material keeps the level constant), at the same sample position.
#include "studyapp/core/playback_mixer.hpp"

#include <algorithm>
#include <cmath>

namespace ms {

PlaybackMixer::PlaybackMixer(double sample_rate_hz, double crossfade_s)
    : sample_rate_hz_(sample_rate_hz),
      crossfade_frames_(std::max<std::size_t>(1, std::size_t(std::lround(crossfade_s * sample_rate_hz)))) {}

void PlaybackMixer::set_stimuli(std::vector<Samples> stimuli) {
  const std::lock_guard<std::mutex> lock(stimuli_mutex_);
  stimuli_ = std::move(stimuli);
  stop_ = false;  // nothing plays: a stop still pending must not swallow the next play
  restart_ = false;
  playing_ = false;
  current_ = -1;
  requested_ = -1;
  position_ = 0;
  fading_from_ = -1;
  fade_left_ = 0;
}

std::size_t PlaybackMixer::count() const {
  const std::lock_guard<std::mutex> lock(stimuli_mutex_);
  return stimuli_.size();
}

void PlaybackMixer::set_loop(bool loop) { loop_ = loop; }

void PlaybackMixer::play(std::size_t index) {
  stop_ = false;  // a stop given before this play (same render period) is superseded by it
  restart_ = true;
  requested_ = int(index);
  playing_ = true;
}

void PlaybackMixer::switch_to(std::size_t index) {
  if (!playing_) {
    play(index);
    return;
  }
  requested_ = int(index);
}

void PlaybackMixer::stop() {
  requested_ = -1;  // a pending play or switch is cancelled in order, here, not by the audio thread
  stop_ = true;
}

std::size_t PlaybackMixer::render(float* out, std::size_t frames) {
  std::fill(out, out + frames, 0.0f);
  const std::unique_lock<std::mutex> lock(stimuli_mutex_, std::try_to_lock);
  if (!lock.owns_lock()) return 0;  // the stimuli are being replaced: silence this period
  if (stop_.exchange(false)) {
    playing_ = false;
    fade_left_ = 0;
    return 0;
  }
  const int requested = requested_.exchange(-1);
  std::size_t pos = position_;
  if (requested >= 0 && requested < int(stimuli_.size())) {
    const bool restart = restart_.exchange(false);
    if (restart || current_ < 0) {
      pos = 0;
      fade_left_ = 0;
    } else if (requested != current_) {
      fading_from_ = current_;
      fade_left_ = crossfade_frames_;
    }
    current_ = requested;
  }
  if (!playing_ || current_ < 0 || current_ >= int(stimuli_.size())) return 0;
  const std::vector<float>& now = *stimuli_[std::size_t(current_)];
  const std::vector<float>* before =
      fade_left_ > 0 && fading_from_ >= 0 ? stimuli_[std::size_t(fading_from_)].get() : nullptr;
  // Stimuli of one trial may differ in length: the longest sets the loop length.
  std::size_t length = 0;
  for (const auto& s : stimuli_) length = std::max(length, s->size());
  std::size_t written = 0;
  for (std::size_t i = 0; i < frames; ++i) {
    if (pos >= length) {
      if (!loop_ || length == 0) {
        playing_ = false;
        break;
      }
      pos = 0;
    }
    float v = pos < now.size() ? now[pos] : 0.0f;
    if (before && fade_left_ > 0) {
      const float g = float(fade_left_) / float(crossfade_frames_);
      const float old = pos < before->size() ? (*before)[pos] : 0.0f;
      v = g * old + (1.0f - g) * v;
      --fade_left_;
    }
    out[i] = v;
    ++pos;
    ++written;
  }
  position_ = pos;
  return written;
}

}  // namespace ms
