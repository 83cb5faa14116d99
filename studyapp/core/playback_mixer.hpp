// Playback of one trial's stimuli for an audio callback: play from the start, switch to another
// stimulus at the same sample position (MUSHRA's seamless switching, with a 5 ms crossfade so the
// switch does not click), optional looping, stop. The GUI thread calls the commands; the audio thread
// calls render(), which never allocates or blocks (it outputs silence if the stimuli are being replaced).
#pragma once
#include <atomic>
#include <cstddef>
#include <mutex>
#include <vector>

#include "studyapp/core/stimulus_cache.hpp"

namespace ms {

class PlaybackMixer {
 public:
  explicit PlaybackMixer(double sample_rate_hz, double crossfade_s = 0.005);

  void set_stimuli(std::vector<Samples> stimuli);  // stops playback
  void set_loop(bool loop);
  void play(std::size_t index);       // from the start
  void switch_to(std::size_t index);  // same position (starts at 0 if stopped)
  void stop();

  // Audio thread: writes `frames` mono samples; returns the frames that carried sound.
  std::size_t render(float* out, std::size_t frames);

  bool playing() const { return playing_.load(); }
  int current() const { return current_.load(); }            // -1 when nothing was played
  std::size_t position_frames() const { return position_.load(); }
  std::size_t count() const;

 private:
  struct Command { int index = -1; bool restart = false; bool stop = false; };
  double sample_rate_hz_;
  std::size_t crossfade_frames_;
  mutable std::mutex stimuli_mutex_;         // held by set_stimuli; render only try_locks it
  std::vector<Samples> stimuli_;
  std::atomic<int> requested_{-1};           // pending command, applied at the next render
  std::atomic<bool> restart_{false}, stop_{false}, loop_{false}, playing_{false};
  std::atomic<int> current_{-1};
  std::atomic<std::size_t> position_{0};
  int fading_from_ = -1;                     // audio thread only
  std::size_t fade_left_ = 0;
};

}  // namespace ms
