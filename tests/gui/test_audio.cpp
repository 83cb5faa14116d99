// Audio out: a missing device or --audio null is a message and a working null output (never a crash),
// the MixerDevice a QAudioSink pulls renders the mixer as float or Int16, the calibration tone's level
// and frequency, and the start page's calibration button.
#include <QLabel>

#include <cmath>
#include <cstdint>

#include "gui_fixture.hpp"
#include "studyapp/gui/audio_output.hpp"
#include "studyapp/gui/mixer_device.hpp"

using namespace gui_test;

TEST(Audio, MissingDeviceIsAMessageAndANullOutput) {
  app();
  ms::gui::AudioOutput out(44100, "no such sound card");
  EXPECT_TRUE(out.is_null());
  EXPECT_NE(out.message().indexOf("was not found"), -1) << out.message().toStdString();
  // The null output still plays in real time: a 1 s tone is playing, then over.
  out.mixer().set_stimuli({ms::gui::calibration_tone(44100)});
  out.mixer().play(0);
  EXPECT_TRUE(out.mixer().playing());
  EXPECT_TRUE(wait_until([&] { return !out.mixer().playing(); }, 5000));
}

TEST(Audio, NullOutputHasNoMessage) {
  app();
  ms::gui::AudioOutput out(48000, "null");
  EXPECT_TRUE(out.is_null());
  EXPECT_TRUE(out.message().isEmpty());
}

TEST(Audio, StartPageShowsAMissingDevice) {
  const std::string dir = fresh_dir("audio-missing");
  ms::gui::AppOptions o = demo_options("P9", dir + "/r.sqlite");
  o.audio = "no such sound card";
  ms::gui::MainWindow w(o);
  auto* message = w.findChild<QLabel*>("audioMessage");
  ASSERT_NE(message, nullptr);
  EXPECT_FALSE(message->text().isEmpty());
  EXPECT_EQ(w.start_page().audio_device(), "null");
}

TEST(Audio, CalibrationToneIs1kHzAtMinus20dBFS) {
  const auto tone = ms::gui::calibration_tone(48000);
  ASSERT_EQ(tone->size(), 48000u);
  float peak = 0;
  int crossings = 0;
  for (std::size_t i = 1; i < tone->size(); ++i) {
    peak = std::max(peak, std::abs((*tone)[i]));
    crossings += ((*tone)[i - 1] < 0) != ((*tone)[i] < 0);
  }
  EXPECT_NEAR(peak, 0.1f, 1e-3f);
  EXPECT_NEAR(crossings, 2000, 2);  // two zero crossings per period over 1 s
}

TEST(Audio, MixerDeviceRendersFloatAndInt16) {
  ms::PlaybackMixer mixer(48000);
  mixer.set_stimuli({ms::gui::calibration_tone(48000)});
  mixer.play(0);
  ms::gui::MixerDevice as_float(mixer, QAudioFormat::Float);
  as_float.open(QIODevice::ReadOnly);
  std::vector<float> f(4800);
  ASSERT_EQ(as_float.read(reinterpret_cast<char*>(f.data()), 4800 * 4), 4800 * 4);
  float peak = 0;
  for (float v : f) peak = std::max(peak, std::abs(v));
  EXPECT_GT(peak, 0.05f);  // past the 10 ms ramp the tone is at 0.1

  ms::gui::MixerDevice as_int16(mixer, QAudioFormat::Int16);
  as_int16.open(QIODevice::ReadOnly);
  std::vector<std::int16_t> s(10000);  // more than the 4096-frame conversion buffer
  ASSERT_EQ(as_int16.read(reinterpret_cast<char*>(s.data()), 20000), 20000);
  int peak16 = 0;
  for (std::int16_t v : s) peak16 = std::max(peak16, std::abs(static_cast<int>(v)));
  EXPECT_NEAR(peak16, 3277, 40);  // 0.1 of full scale

  mixer.stop();
  ASSERT_EQ(as_float.read(reinterpret_cast<char*>(f.data()), 4800 * 4), 4800 * 4);
  ASSERT_EQ(as_float.read(reinterpret_cast<char*>(f.data()), 4800 * 4), 4800 * 4);
  for (float v : f) ASSERT_EQ(v, 0.0f);  // silence once stopped (after the crossfade)
}

TEST(Audio, CalibrationButtonPlaysTheTone) {
  const std::string dir = fresh_dir("audio-calibrate");
  ms::gui::MainWindow w(demo_options("P9", dir + "/r.sqlite"));
  click(&w.start_page(), "calibrate");
  EXPECT_TRUE(w.controller()->audio().mixer().playing());
  EXPECT_EQ(w.controller()->audio().mixer().count(), 1u);
}
