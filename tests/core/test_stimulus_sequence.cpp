// Sequence stimuli ({sequence: [...], onsets_s: [...], gains_db: [...]}): the sound is the sum of the
// parts at their onsets, sample by sample; its hash changes with any part, onset, gain or order and
// not with the names; every mistake is one located problem, the same in `protocol check` and at a
// session start; the parts stay confined like any stimulus.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "studyapp/core/protocol_parser.hpp"
#include "studyapp/core/protocol_validator.hpp"
#include "studyapp/core/stimulus_cache.hpp"
#include "studyapp/core/stimulus_sequence.hpp"
#include "support/test_util.hpp"
#include "synthesis/audio_file.hpp"
#include "synthesis/paramset.hpp"
#include "synthesis/stimulus.hpp"

namespace ms {
namespace {

std::string all(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& p : v) s += p + "\n";
  return s;
}

// Two one-mode sets and a recording; `stimuli` is appended to their definitions.
std::string study(const test::TempDir& dir, const std::string& stimuli, const std::string& file = "study.yaml") {
  dir.write("sets/a.yaml", "sample_rate: 44100\nduration_s: 0.3\nmodes: [{freq_hz: 440, decay_per_s: 8, amp: 0.5}]\n"
                           "excitation: {type: impulse}\nlevel: {normalize: none}\n");
  dir.write("sets/b.yaml", "sample_rate: 44100\nduration_s: 0.2\nmodes: [{freq_hz: 1250, decay_per_s: 20, amp: 0.4}]\n"
                           "excitation: {type: impulse}\nlevel: {normalize: none}\n");
  if (!std::filesystem::exists(dir.file("audio/r.wav"))) {
    std::filesystem::create_directories(dir.file("audio"));
    std::vector<float> r(3000);
    for (std::size_t n = 0; n < r.size(); ++n) r[n] = 0.3f * float(std::sin(0.05 * double(n))) * float(n % 7) / 7.0f;
    write_wav(dir.file("audio/r.wav"), Audio{44100, 1, r}, SampleFormat::float32);
  }
  return dir.write(file, "study: seq\nsample_rate: 44100\nstimuli:\n"
                         "  a: {paramset: sets/a.yaml}\n"
                         "  b: {paramset: sets/b.yaml}\n"
                         "  r: {file: audio/r.wav}\n" +
                             stimuli + "blocks:\n  - {type: ab, id: x, mode: bipolar, pairs: [[a, b]]}\n");
}

std::vector<std::string> problems_of(const std::string& path) { return check_protocol_file(path).problems; }

// What a session start meets: the first error of the check, else of the stimulus cache rendering all.
std::string start_error(const std::string& path) {
  const ProtocolCheck c = check_protocol_file(path);
  if (!c.problems.empty()) return c.problems.front();
  try {
    StimulusCache cache(*c.protocol, "");
    cache.prepare_all();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(StimulusSequence, IsThePartsSummedAtTheirOnsetsSampleBySample) {
  test::TempDir dir;
  const Protocol p = load_protocol(study(dir, "  bounce: {sequence: [a, b, r, a], onsets_s: [0, 0.25, 0.3100113, 0.5],"
                                              " gains_db: [0, -6, 3, -12]}\n"));
  StimulusCache cache(p, dir.file("cache"));
  const Samples seq = cache.samples("bounce");
  // The parts made independently of the cache: the sets rendered, the recording read.
  const std::vector<float> a = render_stimulus(load_paramset(dir.file("sets/a.yaml"))).audio.samples;
  const std::vector<float> b = render_stimulus(load_paramset(dir.file("sets/b.yaml"))).audio.samples;
  const std::vector<float> r = read_audio(dir.file("audio/r.wav")).samples;
  struct Part {
    const std::vector<float>* x;
    std::size_t at;
    double gain;
  } parts[] = {{&a, 0, 1.0}, {&b, 11025, std::pow(10.0, -6.0 / 20)}, {&r, 13671, std::pow(10.0, 3.0 / 20)},
               {&a, 22050, std::pow(10.0, -12.0 / 20)}};  // 0.3100113 s x 44100 = 13671.498: frame 13671
  ASSERT_EQ(seq->size(), 22050 + a.size());  // the last strike's end
  std::vector<double> expected(seq->size(), 0.0);
  for (const Part& part : parts)
    for (std::size_t n = 0; n < part.x->size(); ++n) expected[part.at + n] += part.gain * double((*part.x)[n]);
  double peak = 0.0;
  for (std::size_t n = 0; n < seq->size(); ++n) {
    ASSERT_NEAR((*seq)[n], expected[n], 1e-7) << "frame " << n;
    peak = std::max(peak, std::abs(expected[n]));
  }
  EXPECT_GT(peak, 0.1);  // the parts do sound
  EXPECT_EQ((*seq)[11024], float(expected[11024]));  // before b starts only a (and nothing else) sounds
  // Cached on disk by its hash like any stimulus, and read back the same.
  EXPECT_TRUE(std::filesystem::exists(dir.file("cache/" + cache.hash("bounce") + ".wav")));
  StimulusCache again(p, dir.file("cache"));
  EXPECT_EQ(*again.samples("bounce"), *seq);
  EXPECT_EQ(again.rendered_count(), 0u);
}

TEST(StimulusSequence, ASequenceOfSequencesNestsTheOnsets) {
  test::TempDir dir;
  const Protocol p = load_protocol(study(dir, "  two: {sequence: [a, b], onsets_s: [0, 0.1]}\n"
                                              "  four: {sequence: [two, two], onsets_s: [0, 0.5], gains_db: [0, -6]}\n"
                                              "  flat: {sequence: [a, b, a, b], onsets_s: [0, 0.1, 0.5, 0.6],"
                                              " gains_db: [0, 0, -6, -6]}\n"));
  StimulusCache cache(p, "");
  const Samples nested = cache.samples("four"), flat = cache.samples("flat");
  ASSERT_EQ(nested->size(), flat->size());
  for (std::size_t n = 0; n < flat->size(); ++n) ASSERT_NEAR((*nested)[n], (*flat)[n], 1e-7) << n;
}

TEST(StimulusSequence, TheHashFollowsEveryPartOnsetGainAndOrderButNotTheNames) {
  test::TempDir dir;
  const auto hash_of = [&](const std::string& stimuli, const std::string& file = "study.yaml") {
    const Protocol p = load_protocol(study(dir, stimuli, file));
    return StimulusCache(p, "").hash("s");
  };
  const std::string base = hash_of("  s: {sequence: [a, b, r], onsets_s: [0, 0.25, 0.5], gains_db: [0, -6, -3]}\n");
  EXPECT_EQ(base, hash_of("  s: {sequence: [a, b, r], onsets_s: [0, 0.25, 0.5], gains_db: [0, -6, -3]}\n"));
  for (const std::string& changed : {
           "  s: {sequence: [a, b, r], onsets_s: [0, 0.25, 0.51], gains_db: [0, -6, -3]}\n",   // an onset
           "  s: {sequence: [a, b, r], onsets_s: [0, 0.25, 0.5], gains_db: [0, -6, -2]}\n",    // a gain
           "  s: {sequence: [b, a, r], onsets_s: [0, 0.25, 0.5], gains_db: [0, -6, -3]}\n",    // the order
           "  s: {sequence: [a, b], onsets_s: [0, 0.25], gains_db: [0, -6]}\n",                // a part fewer
           "  s: {sequence: [a, b, r], onsets_s: [0, 0.25, 0.5]}\n"})                          // gains 0 dB
    EXPECT_NE(base, hash_of(changed)) << changed;
  // A part's own recipe: an override of one part's set.
  EXPECT_NE(base, hash_of("  bq: {paramset: sets/b.yaml, set: {amp_scale: 0.9}}\n"
                          "  s: {sequence: [a, bq, r], onsets_s: [0, 0.25, 0.5], gains_db: [0, -6, -3]}\n"));
  // A part's recording: other bytes, other hash.
  std::vector<float> other(3000, 0.01f);
  write_wav(dir.file("audio/r.wav"), Audio{44100, 1, other}, SampleFormat::float32);
  EXPECT_NE(base, hash_of("  s: {sequence: [a, b, r], onsets_s: [0, 0.25, 0.5], gains_db: [0, -6, -3]}\n"));
  std::filesystem::remove(dir.file("audio/r.wav"));
  const std::string restored = hash_of("  s: {sequence: [a, b, r], onsets_s: [0, 0.25, 0.5], gains_db: [0, -6, -3]}\n");
  EXPECT_EQ(restored, base);
  // The same parts under other names in another protocol: the same sound, the same hash.
  EXPECT_EQ(base, hash_of("  x1: {paramset: sets/a.yaml}\n  x2: {file: audio/r.wav}\n"
                          "  s: {sequence: [x1, b, x2], onsets_s: [0, 0.25, 0.5], gains_db: [0, -6, -3]}\n",
                          "other.yaml"));
  // Not the hash of any part, nor of a plain list of the part hashes.
  const Protocol p = load_protocol(dir.file("study.yaml"));
  StimulusCache cache(p, "");
  for (const char* part : {"a", "b", "r"}) EXPECT_NE(cache.hash("s"), cache.hash(part));
  EXPECT_EQ(cache.hash("s"), sequence_hash({{cache.hash("a"), 0, 0}, {cache.hash("b"), 0.25, -6}, {cache.hash("r"), 0.5, -3}},
                                           44100));
}

TEST(StimulusSequence, EveryMistakeIsOneLocatedProblem) {
  test::TempDir dir;
  struct Case {
    std::string stimuli, where, message;
  } cases[] = {
      {"  s: {sequence: [a, bb], onsets_s: [0, 0.2]}\n", "study.yaml:7:21:", "unknown stimulus 'bb' (did you mean 'b'?)"},
      {"  s: {sequence: [a, b, a], onsets_s: [0, 0.4, 0.3]}\n", "study.yaml:7:47:",
       "stimuli.s.onsets_s[2]: onsets must rise: 0.3 s is not later than the onset before it"},
      {"  s: {sequence: [a, b], onsets_s: [0, 0]}\n", "study.yaml:7:39:", "stimuli.s.onsets_s[1]: onsets must rise"},
      {"  s: {sequence: [a, b, a], onsets_s: [0, 0.2]}\n", "study.yaml:7:38:",
       "stimuli.s.onsets_s: has 2 values but 'sequence' names 3 stimuli"},
      {"  s: {sequence: [a, b], onsets_s: [0, 0.2], gains_db: [0]}\n", "study.yaml:7:55:",
       "stimuli.s.gains_db: has 1 values but 'sequence' names 2 stimuli"},
      {"  s: {sequence: [a, s], onsets_s: [0, 0.2]}\n", "study.yaml:7:21:",
       "stimuli.s.sequence[1]: a sequence cannot contain itself"},
      {"  s: {sequence: [a, b]}\n", "study.yaml:7:6:", "a sequence needs 'onsets_s'"},
      {"  s: {sequence: [], onsets_s: []}\n", "study.yaml:7:17:", "expected a list of stimulus names"},
      {"  s: {sequence: a, onsets_s: [0]}\n", "study.yaml:7:17:", "expected a list of stimulus names"},
      {"  s: {sequence: [a, b], onsets_s: [-0.1, 0.2]}\n", "study.yaml:7:36:", "stimuli.s.onsets_s[0]"},
      {"  s: {sequence: [a, b], onsets_s: [0, 601]}\n", "study.yaml:7:39:", "absurd onset (more than 600 s)"},
      {"  s: {sequence: [a, b], onsets_s: [0, 0.2], gains_db: [0, 41]}\n", "study.yaml:7:59:",
       "stimuli.s.gains_db[1]: a gain must lie between -120 and +40 dB, got 41"},
      {"  s: {sequence: [a, b], onsets_s: [0, 0.2], gains_db: [0, .nan]}\n", "study.yaml:7:59:", "stimuli.s.gains_db[1]: '.nan' is not a finite number"},
      {"  s: {sequence: [a, b], onset_s: [0, 0.2]}\n", "study.yaml:7:", "did you mean 'onsets_s'"},
      {"  s: {sequence: [a, b], file: audio/r.wav, onsets_s: [0, 1]}\n", "study.yaml:7:6:",
       "needs exactly one of 'paramset', 'derive', 'file' or 'sequence'"},
      // Longer cycles: through another sequence and through a derived stimulus.
      {"  s: {sequence: [a, t], onsets_s: [0, 0.2]}\n  t: {sequence: [b, s], onsets_s: [0, 0.2]}\n", "study.yaml:7:3:",
       "stimulus 's': the sequence contains itself through 't'"},
      {"  s: {sequence: [a, lp], onsets_s: [0, 0.2]}\n  lp: {derive: s, lowpass_hz: 3500}\n", "study.yaml:7:3:",
       "stimulus 's': the sequence contains itself through 'lp'"},
  };
  for (const Case& c : cases) {
    const std::string path = study(dir, c.stimuli);
    const auto problems = problems_of(path);
    ASSERT_GE(problems.size(), 1u) << c.stimuli;
    EXPECT_NE(problems[0].find(c.where), std::string::npos) << c.stimuli << all(problems);
    EXPECT_NE(problems[0].find(c.message), std::string::npos) << c.stimuli << all(problems);
    // One problem, except the two-sequence cycle, which both sequences report.
    if (c.stimuli.find("t: {sequence") == std::string::npos) EXPECT_EQ(problems.size(), 1u) << c.stimuli << all(problems);
    // A session start meets the same first problem (never a loop, never a later surprise).
    EXPECT_EQ(start_error(path), problems[0]) << c.stimuli;
  }
  // A good sequence checks clean and starts.
  const std::string good = study(dir, "  s: {sequence: [a, b], onsets_s: [0, 0.2], gains_db: [0, -3]}\n");
  EXPECT_TRUE(problems_of(good).empty()) << all(problems_of(good));
  EXPECT_EQ(start_error(good), "");
}

TEST(StimulusSequence, APartStaysConfinedAndIsReportedOnceWhereItIsDefined) {
  test::TempDir dir;
  const char* set = "sample_rate: 44100\nduration_s: 0.1\nmodes: [{freq_hz: 440, decay_per_s: 8, amp: 0.5}]\n";
  dir.write("outside/x.yaml", set);
  dir.write("study/sets/a.yaml", set);
  const std::string path = dir.write("study/p.yaml", "study: seq\nsample_rate: 44100\nstimuli:\n"
                                                     "  a: {paramset: sets/a.yaml}\n"
                                                     "  far: {paramset: ../outside/x.yaml}\n"
                                                     "  s: {sequence: [a, far], onsets_s: [0, 0.2]}\n"
                                                     "blocks:\n  - {type: ab, id: x, mode: bipolar, pairs: [[a, s]]}\n");
  const auto problems = problems_of(path);
  ASSERT_EQ(problems.size(), 1u) << all(problems);
  EXPECT_NE(problems[0].find("p.yaml:5:19: stimulus 'far': path '../outside/x.yaml' is outside the protocol's folder"),
            std::string::npos)
      << problems[0];
  EXPECT_EQ(start_error(path), problems[0]);
}

TEST(StimulusSequence, ASoundPast600SecondsIsRefusedAtTheSequence) {
  test::TempDir dir;
  dir.write("sets/k.yaml", "sample_rate: 8000\nduration_s: 0.1\nmodes: [{freq_hz: 100, decay_per_s: 8, amp: 0.5}]\n");
  const std::string path =
      dir.write("long.yaml", "study: long\nsample_rate: 8000\nstimuli:\n  k: {paramset: sets/k.yaml}\n"
                             "  one: {sequence: [k, k], onsets_s: [0, 599]}\n"
                             "  two: {sequence: [one, one], onsets_s: [0, 500]}\n"
                             "blocks:\n  - {type: ab, id: x, mode: bipolar, pairs: [[one, two]]}\n");
  EXPECT_TRUE(problems_of(path).empty()) << all(problems_of(path));
  const Protocol p = load_protocol(path);
  StimulusCache cache(p, "");
  EXPECT_EQ(cache.samples("one")->size(), 599u * 8000u + 800u);
  try {
    cache.samples("two");
    FAIL() << "a 1099.1 s sequence was rendered";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("long.yaml:6:3: stimulus 'two': the sequence would last 1099.1 s, more than 600 s"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace ms
