// Protocol inputs that must not escape or mislead: one confinement for every path a protocol reaches
// (through its parameter sets' modes CSVs too), the study id as an identifier, duplicate keys, and
// `protocol check` running every check a session start runs, with each problem at its line.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

#include "studyapp/core/autopilot.hpp"
#include "studyapp/core/protocol_parser.hpp"
#include "studyapp/core/protocol_validator.hpp"
#include "studyapp/core/stimulus_cache.hpp"
#include "support/test_util.hpp"
#include "synthesis/audio_file.hpp"

namespace {

using ms::test::TempDir;

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string all(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& p : v) s += p + "\n";
  return s;
}

bool has(const std::vector<std::string>& problems, const std::string& needle) {
  return std::any_of(problems.begin(), problems.end(),
                     [&](const std::string& p) { return p.find(needle) != std::string::npos; });
}

// What a session start does before the first trial (autopilot, studyapp): the check, then the
// stimulus cache renders or reads every stimulus. The first error, or "".
std::string start_error(const std::string& protocol_path) {
  const ms::ProtocolCheck c = ms::check_protocol_file(protocol_path);
  if (!c.protocol) return c.problems.empty() ? "" : c.problems.front();
  try {
    ms::StimulusCache cache(*c.protocol, "");
    cache.prepare_all();
  } catch (const ms::InputError& e) {
    return e.what();
  }
  return "";
}

const char* kSet = "sample_rate: 44100\nduration_s: 0.2\nmodes: [{freq_hz: 440, decay_per_s: 6, amp: 0.5}]\n";

std::string protocol_with(const std::string& stimuli) {
  return "study: t\nsample_rate: 44100\nstimuli:\n" + stimuli +
         "blocks:\n  - {type: identify, id: i, stimuli: [a], labels: [x, y]}\n";
}

}  // namespace

TEST(ProtocolConfinement, AParameterSetsModesCsvIsConfinedToo) {
  TempDir dir;
  dir.write("outside/m.csv", "freq_hz,decay_per_s,amp\n440,3,1\n");
  dir.write("study/sets/s.yaml", "duration_s: 0.2\nmodes: ../../outside/m.csv\n");
  dir.write("study/sets/etc.yaml", "duration_s: 0.2\nmodes: /etc/passwd\n");
  const std::string path =
      dir.write("study/p.yaml", protocol_with("  a: {paramset: sets/s.yaml}\n  b: {paramset: sets/etc.yaml}\n"));
  const auto problems = ms::check_protocol_file(path).problems;
  ASSERT_EQ(problems.size(), 2u) << all(problems);
  EXPECT_TRUE(has(problems, "s.yaml:2:8: modes: path '../../outside/m.csv' is outside the protocol's folder")) << all(problems);
  EXPECT_TRUE(has(problems, "etc.yaml:2:8: modes: path '/etc/passwd' is outside the protocol's folder")) << all(problems);
  // A session start refuses it as well (the cache applies the same confinement).
  EXPECT_NE(start_error(path).find("is outside the protocol's folder"), std::string::npos);
  // With the permission the protocol checks clean except for /etc/passwd, which is no modes CSV.
  ms::ValidateOptions o;
  o.allow_outside = true;
  const auto allowed = ms::check_protocol_file(path, o).problems;
  ASSERT_EQ(allowed.size(), 1u) << all(allowed);
  EXPECT_EQ(allowed[0].rfind("/etc/passwd:", 0), 0u) << all(allowed);
}

TEST(ProtocolConfinement, AFifoOrDeviceAsARecordingIsRefusedWithoutBlocking) {
  TempDir dir;
  ASSERT_EQ(::mkfifo(dir.file("pipe.wav").c_str(), 0600), 0);
  const std::string path = dir.write("p.yaml", protocol_with("  a: {file: pipe.wav}\n"));
  const auto problems = ms::check_protocol_file(path).problems;
  ASSERT_EQ(problems.size(), 1u) << all(problems);
  EXPECT_EQ(problems[0], path + ":4:13: stimulus 'a': 'pipe.wav': is a FIFO (named pipe), not a regular file");
}

TEST(StudyId, AStudyIdThatIsNoIdentifierIsRefusedAtItsLine) {
  TempDir dir;
  dir.write("s.yaml", kSet);
  const std::string path = dir.write("p.yaml", "study: \"../../../x\"\n" + protocol_with("  a: {paramset: s.yaml}\n").substr(9));
  const auto problems = ms::check_protocol_file(path).problems;
  ASSERT_EQ(problems.size(), 1u) << all(problems);
  EXPECT_EQ(problems[0].rfind(path + ":1:8: study: '../../../x' is not an id", 0), 0u) << problems[0];
  EXPECT_THROW(ms::default_db_path(path, "../../../x"), ms::InputError);
  EXPECT_EQ(ms::default_db_path("/a/p.yaml", "demo"), "/a/results/demo.sqlite");
}

TEST(ProtocolDuplicates, ADuplicateKeyNamesBothLines) {
  TempDir dir;
  const std::string path = dir.write("p.yaml", "study: t\nblocks: [{type: instructions, text: hi}]\nstudy: u\n");
  const auto problems = ms::check_protocol_file(path).problems;
  ASSERT_EQ(problems.size(), 1u) << all(problems);
  EXPECT_EQ(problems[0], path + ":3:1: duplicate key 'study' (first at line 1, column 1)");
}

TEST(CheckParity, CheckReportsEveryProblemASessionStartWouldMeet) {
  TempDir dir;
  dir.write("s48.yaml", std::string("sample_rate: 48000\n") + (kSet + 19));
  dir.write("text.wav", "this is not audio\n");
  ms::write_wav(dir.file("r48.wav"), ms::Audio{48000, 1, std::vector<float>(4800, 0.1f)}, ms::SampleFormat::float32);
  {  // A float WAV holding a NaN (write_wav refuses to write one).
    std::vector<float> x(441, 0.1f);
    ms::write_wav(dir.file("nan.wav"), ms::Audio{44100, 1, x}, ms::SampleFormat::float32);
    std::string bytes = slurp(dir.file("nan.wav"));
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(bytes.data() + bytes.size() - 4 * 100, &nan, 4);
    dir.write("nan.wav", bytes);
  }
  struct Case {
    const char* stimulus;
    const char* expect;
  } cases[] = {
      {"  a: {paramset: s48.yaml}\n", ":4:17: stimulus 'a': parameter set renders at 48000 Hz but the protocol's sample_rate is 44100"},
      {"  a: {file: text.wav}\n", ":4:13: stimulus 'a': 'text.wav': not a readable audio file"},
      {"  a: {file: r48.wav}\n", ":4:13: stimulus 'a': recording 'r48.wav' is at 48000 Hz but the protocol's sample_rate is 44100"},
      {"  a: {file: nan.wav}\n", ":4:13: stimulus 'a': 'nan.wav': audio contains NaN or infinite samples"},
  };
  for (const Case& c : cases) {
    const std::string path = dir.write("p.yaml", protocol_with(c.stimulus));
    const auto problems = ms::check_protocol_file(path).problems;
    ASSERT_EQ(problems.size(), 1u) << c.stimulus << all(problems);
    EXPECT_EQ(problems[0].rfind(path + c.expect, 0), 0u) << problems[0];
    // The start refuses the same stimulus with the same line (it may stop at the check already).
    const std::string start = start_error(path);
    EXPECT_EQ(start.rfind(path + c.expect, 0), 0u) << start;
  }
}

TEST(ProtocolMessages, OneBadFieldInTheOnlyBlockIsOneProblem) {
  TempDir dir;
  dir.write("s.yaml", kSet);
  const std::string path = dir.write("p.yaml", "study: t\nstimuli:\n  a: {paramset: s.yaml}\n"
                                               "blocks:\n  - {type: identify, stimuli: [a], labels: [x], repeats: 0}\n");
  const auto problems = ms::check_protocol_file(path).problems;
  ASSERT_EQ(problems.size(), 1u) << all(problems);
  EXPECT_EQ(problems[0].rfind(path + ":5:58: blocks[0].repeats: must be between 1 and 1000", 0), 0u) << problems[0];
}

TEST(ProtocolMessages, ABadStimulusIsNotAlsoAnUnknownOne) {
  TempDir dir;
  const std::string path = dir.write("p.yaml", "study: t\nstimuli:\n  a: {paramset: s.yaml, bogus: 1}\n"
                                               "blocks:\n  - {type: identify, stimuli: [a], labels: [x]}\n");
  const auto problems = ms::check_protocol_file(path).problems;
  ASSERT_EQ(problems.size(), 1u) << all(problems);
  EXPECT_NE(problems[0].find(":3:25: unknown key 'stimuli.a.bogus'"), std::string::npos) << problems[0];
}

TEST(ProtocolMessages, OverridesAreReportedAtTheProtocolsLine) {
  TempDir dir;
  dir.write("s.yaml", kSet);
  const std::string path = dir.write(
      "p.yaml", protocol_with("  a: {paramset: s.yaml, set: {duration_s: 0}}\n"
                              "  b: {paramset: s.yaml, set: {excitation: {type: hertz}}}\n"));
  const auto problems = ms::check_protocol_file(path).problems;
  ASSERT_EQ(problems.size(), 2u) << all(problems);
  EXPECT_EQ(problems[0], path + ":4:43: stimulus 'a': duration_s: must be greater than 0, got 0");
  EXPECT_EQ(problems[1], path + ":5:50: stimulus 'b': excitation: a finite contact needs 'contact_s'");
}

TEST(ProtocolMessages, AnEmptyOrScalarProtocolIsReportedAtLineOne) {
  TempDir dir;
  for (const char* text : {"", "just text\n"}) {
    const std::string path = dir.write("p.yaml", text);
    const auto problems = ms::check_protocol_file(path).problems;
    ASSERT_EQ(problems.size(), 1u) << all(problems);
    EXPECT_EQ(problems[0].rfind(path + ":1:1: ", 0), 0u) << problems[0];
  }
}
