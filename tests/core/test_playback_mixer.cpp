// PlaybackMixer: plays from the start, switches at the same sample (crossfaded), loops, stops, and
// renders without allocating.
#include <gtest/gtest.h>

#include <memory>
#include <numeric>

#include "studyapp/core/playback_mixer.hpp"

namespace ms {
namespace {

Samples ramp(std::size_t n, float scale) {
  auto v = std::make_shared<std::vector<float>>(n);
  for (std::size_t i = 0; i < n; ++i) (*v)[i] = scale * float(i);
  return v;
}

TEST(PlaybackMixer, PlaysFromStartAndEnds) {
  PlaybackMixer m(1000.0, 0.005);
  m.set_stimuli({ramp(100, 1.0f)});
  m.play(0);
  std::vector<float> out(64);
  EXPECT_EQ(m.render(out.data(), out.size()), 64u);
  EXPECT_EQ(out[10], 10.0f);
  EXPECT_EQ(m.render(out.data(), out.size()), 36u);  // 100 frames in all
  EXPECT_EQ(out[35], 99.0f);
  EXPECT_EQ(out[36], 0.0f);
  EXPECT_FALSE(m.playing());
}

TEST(PlaybackMixer, SwitchKeepsThePositionWithACrossfade) {
  PlaybackMixer m(1000.0, 0.004);  // 4-frame crossfade
  m.set_stimuli({ramp(100, 1.0f), ramp(100, -1.0f)});
  m.play(0);
  std::vector<float> out(20);
  m.render(out.data(), out.size());
  EXPECT_EQ(m.position_frames(), 20u);
  m.switch_to(1);
  m.render(out.data(), out.size());
  // Frame 20 onwards: fade from +n to -n over 4 frames, then pure -n, sample-aligned.
  EXPECT_FLOAT_EQ(out[0], 1.0f * 20.0f);            // g = 1: all old
  EXPECT_FLOAT_EQ(out[2], 0.5f * 22.0f - 0.5f * 22.0f);
  EXPECT_FLOAT_EQ(out[4], -24.0f);
  EXPECT_FLOAT_EQ(out[19], -39.0f);
  EXPECT_EQ(m.current(), 1);
}

TEST(PlaybackMixer, LoopsAndStops) {
  PlaybackMixer m(1000.0);
  m.set_stimuli({ramp(10, 1.0f)});
  m.set_loop(true);
  m.play(0);
  std::vector<float> out(25);
  EXPECT_EQ(m.render(out.data(), out.size()), 25u);
  EXPECT_EQ(out[10], 0.0f);
  EXPECT_EQ(out[13], 3.0f);
  m.stop();
  EXPECT_EQ(m.render(out.data(), out.size()), 0u);
  EXPECT_FALSE(m.playing());
  EXPECT_EQ(std::accumulate(out.begin(), out.end(), 0.0f), 0.0f);
}

TEST(PlaybackMixer, SwitchWhileStoppedStartsFromZero) {
  PlaybackMixer m(1000.0);
  m.set_stimuli({ramp(10, 1.0f), ramp(10, 2.0f)});
  m.switch_to(1);
  std::vector<float> out(3);
  m.render(out.data(), out.size());
  EXPECT_EQ(out[1], 2.0f);
}

}  // namespace
}  // namespace ms

namespace ms {
namespace {

// The GUI stops the previous trial's sound and a click plays the next one before the audio thread renders
// again: the play must not be swallowed by the stop.
TEST(PlaybackMixer, PlayRightAfterStopOrNewStimuliPlays) {
  PlaybackMixer m(1000.0, 0.005);
  m.set_stimuli({ramp(100, 1.0f)});
  m.play(0);
  std::vector<float> out(10);
  m.render(out.data(), out.size());
  m.stop();
  m.set_stimuli({ramp(100, 2.0f), ramp(100, 3.0f)});
  m.play(1);
  EXPECT_EQ(m.render(out.data(), out.size()), 10u);
  EXPECT_EQ(m.current(), 1);
  EXPECT_EQ(out[4], 12.0f);  // from the start of stimulus 1
  m.stop();
  m.play(0);
  EXPECT_EQ(m.render(out.data(), out.size()), 10u);
  EXPECT_EQ(out[4], 8.0f);
  m.play(1);
  m.stop();  // stop after a play in the same period: silence
  EXPECT_EQ(m.render(out.data(), out.size()), 0u);
  EXPECT_FALSE(m.playing());
}

}  // namespace
}  // namespace ms
