// StimulusCache: parameter sets render exactly as `modalstudy synth` would, anchors are low-passed,
// recordings are read, everything is cached by hash in memory and on disk; bad stimuli are named.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <filesystem>
#include <numbers>

#include "core_fixtures.hpp"
#include "studyapp/core/anchor_lowpass.hpp"
#include "studyapp/core/protocol_parser.hpp"
#include "studyapp/core/stimulus_cache.hpp"
#include "synthesis/audio_file.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/paramset.hpp"
#include "synthesis/stimulus.hpp"

namespace ms {
namespace {

// Level (dB) of a sinusoid of frequency f in x, by correlation.
double tone_db(const std::vector<float>& x, double fs, double f) {
  std::complex<double> acc = 0.0;
  for (std::size_t n = 0; n < x.size(); ++n)
    acc += double(x[n]) * std::polar(1.0, -2.0 * std::numbers::pi * f * double(n) / fs);
  return 20.0 * std::log10(std::abs(acc) + 1e-30);
}

TEST(StimulusCache, RendersLikeSynthAndCachesByHash) {
  test::TempDir dir;
  const Protocol p = load_protocol(testing::write_small_study(dir));
  StimulusCache cache(p, dir.file("cache"));
  const auto direct = render_stimulus(load_paramset(dir.file("sets/low.yaml"))).audio.samples;
  const Samples low = cache.samples("low");
  ASSERT_EQ(*low, direct);
  EXPECT_EQ(cache.hash("low"), load_paramset(dir.file("sets/low.yaml")).recipe_hash);
  EXPECT_NE(cache.hash("lowq"), cache.hash("low"));  // overrides change the recipe
  EXPECT_EQ(cache.samples("low").get(), low.get());  // memory hit: same buffer
  EXPECT_TRUE(std::filesystem::exists(dir.file("cache/" + cache.hash("low") + ".wav")));
  EXPECT_EQ(cache.rendered_count(), 1u);
  // A second cache over the same folder loads from disk instead of rendering.
  StimulusCache again(p, dir.file("cache"));
  EXPECT_EQ(*again.samples("low"), direct);
  EXPECT_EQ(again.rendered_count(), 0u);
}

TEST(StimulusCache, AnchorIsTheReferenceLowPassed) {
  test::TempDir dir;
  const Protocol p = load_protocol(testing::write_small_study(dir));
  StimulusCache cache(p, "");
  const auto ref = cache.samples("low");
  const auto lp = cache.samples("lp");
  ASSERT_EQ(lp->size(), ref->size());
  // low.yaml: 440 Hz (kept) and 5200 Hz (removed by the 3.5 kHz anchor).
  EXPECT_NEAR(tone_db(*lp, 44100, 440) - tone_db(*ref, 44100, 440), 0.0, 0.05);
  EXPECT_LT(tone_db(*lp, 44100, 5200) - tone_db(*ref, 44100, 5200), -60.0);
  EXPECT_NE(cache.hash("lp"), cache.hash("low"));
}

TEST(StimulusCache, LowpassTransitionIsFivePercentWide) {
  const double fs = 44100;
  std::vector<float> x(44100);
  for (std::size_t n = 0; n < x.size(); ++n)
    x[n] = float(std::sin(2 * std::numbers::pi * 3000 * double(n) / fs) + std::sin(2 * std::numbers::pi * 3700 * double(n) / fs));
  const auto y = lowpass_anchor(x, fs, 3500);
  EXPECT_NEAR(tone_db(y, fs, 3000), tone_db(x, fs, 3000), 0.1);         // below 3412.5 Hz: untouched
  EXPECT_LT(tone_db(y, fs, 3700) - tone_db(x, fs, 3700), -60.0);      // above 3587.5 Hz: gone
}

TEST(StimulusCache, RecordingsAndTheirSampleRate) {
  test::TempDir dir;
  std::filesystem::create_directories(dir.file("audio"));
  write_wav(dir.file("audio/rec.wav"), Audio{44100, 2, std::vector<float>(200, 0.25f)}, SampleFormat::float32);
  write_wav(dir.file("audio/rec48.wav"), Audio{48000, 1, std::vector<float>(100, 0.25f)}, SampleFormat::float32);
  const std::string path = dir.write("p.yaml", "study: r\nsample_rate: 44100\nstimuli:\n  rec: {file: audio/rec.wav}\n"
                                               "  bad: {file: audio/rec48.wav}\nblocks:\n"
                                               "  - {type: identify, stimuli: [rec, bad], labels: [a, b]}\n");
  const Protocol p = load_protocol(path);
  StimulusCache cache(p, "");
  EXPECT_EQ(cache.samples("rec")->size(), 100u);  // stereo mixed to mono
  try {
    cache.samples("bad");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("48000 Hz"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("p.yaml:5:"), std::string::npos) << e.what();
  }
}

TEST(StimulusCache, SamplesWithOverridesAreCachedByTheirOwnHash) {
  test::TempDir dir;
  const Protocol p = load_protocol(testing::write_small_study(dir));
  StimulusCache cache(p, "");
  const auto a = cache.samples_with("low", {"amp_scale=0.5"});
  const auto b = cache.samples_with("low", {"amp_scale=0.5"});
  EXPECT_EQ(a.get(), b.get());
  EXPECT_EQ(*a, *cache.samples("lowq"));  // the same recipe as the protocol's lowq
  EXPECT_EQ(cache.hash_with("low", {"amp_scale=0.5"}), cache.hash("lowq"));
  EXPECT_THROW(cache.samples_with("lp", {"amp_scale=2"}), InputError);  // a derived stimulus has no parameters
  EXPECT_THROW(cache.samples_with("low", {"durration_s=2"}), InputError);
}

}  // namespace
}  // namespace ms

namespace ms {
namespace {

TEST(StimulusCache, ParameterValueAsWrittenWithOverrides) {
  test::TempDir dir;
  const Protocol p = load_protocol(testing::write_small_study(dir));
  StimulusCache cache(p, "");
  EXPECT_EQ(cache.parameter_value("low", "duration_s"), 0.5);          // from the file
  EXPECT_EQ(cache.parameter_value("lowq", "amp_scale"), 0.5);          // from the protocol's set:
  EXPECT_FALSE(cache.parameter_value("low", "amp_scale").has_value());  // not written
  EXPECT_FALSE(cache.parameter_value("low", "excitation").has_value()); // a map, not a number
  EXPECT_FALSE(cache.parameter_value("lp", "duration_s").has_value());  // derived: no parameters
}

}  // namespace
}  // namespace ms
