// Protocol parsing, validation (every problem with file:line:column) and seeded scheduling.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "studyapp/core/protocol_parser.hpp"
#include "studyapp/core/protocol_validator.hpp"
#include "studyapp/core/schedule.hpp"
#include "support/test_util.hpp"
#include "synthesis/audio_file.hpp"

namespace {

using ms::test::TempDir;

// A real (short) recording: protocol check reads every recording as a session start does.
void write_recording(const ms::test::TempDir& dir, const std::string& name) {
  ms::write_wav(dir.file(name), ms::Audio{44100, 1, std::vector<float>(441, 0.1f)}, ms::SampleFormat::float32);
}

const std::string kHead =
    "study: t\ntitle: T\nseed: 7\nstimuli:\n"
    "  a: {file: a.wav}\n"
    "  b: {file: b.wav}\n";

// Writes a protocol with two existing (empty) recordings next to it and checks it.
std::vector<std::string> check(const TempDir& dir, const std::string& text, bool allow_outside = false) {
  write_recording(dir, "a.wav");
  write_recording(dir, "b.wav");
  const std::string path = dir.write("p.yaml", text);
  ms::ValidateOptions o;
  o.allow_outside = allow_outside;
  return ms::check_protocol_file(path, o).problems;
}

bool has(const std::vector<std::string>& problems, const std::string& needle) {
  return std::any_of(problems.begin(), problems.end(),
                     [&](const std::string& p) { return p.find(needle) != std::string::npos; });
}

std::string all(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& p : v) s += p + "\n";
  return s;
}

}  // namespace

TEST(Protocol, ValidProtocolHasNoProblems) {
  TempDir dir;
  const auto p = check(dir, kHead + "blocks:\n  - {type: ab, id: x, pairs: [[a, b]]}\n");
  EXPECT_TRUE(p.empty()) << all(p);
}

TEST(Protocol, YamlSyntaxErrorNamesLineAndColumn) {
  TempDir dir;
  const auto p = check(dir, kHead + "blocks:\n  - {type: ab, pairs: [[a, b]\n");
  ASSERT_EQ(p.size(), 1u) << all(p);
  EXPECT_TRUE(has(p, dir.file("p.yaml") + ":")) << all(p);
  EXPECT_TRUE(has(p, "YAML syntax error")) << all(p);
}

TEST(Protocol, UnknownBlockTypeSuggestsNearest) {
  TempDir dir;
  const auto p = check(dir, kHead + "blocks:\n  - {type: mushrra, reference: a, conditions: [b]}\n");
  ASSERT_EQ(p.size(), 1u) << all(p);
  EXPECT_EQ(p[0], dir.file("p.yaml") + ":8:12: unknown block type 'mushrra' (did you mean 'mushra'?)");
}

TEST(Protocol, AQuestionWithoutItsTextIsNamed) {
  TempDir dir;
  const auto p = check(dir, "study: t\nstimuli:\n  a: {file: a.wav}\n"
                            "blocks:\n  - {type: questionnaire, id: q, questions: [{id: headphones}]}\n");
  ASSERT_EQ(p.size(), 1u) << all(p);
  EXPECT_EQ(p[0], dir.file("p.yaml") + ":5:46: blocks[0].questions[0].text: missing: a question needs its text");
}

TEST(Protocol, MissingStimulusSuggestsNearest) {
  TempDir dir;
  const auto p = check(dir, "study: t\nstimuli:\n  steel: {file: a.wav}\n  glass: {file: b.wav}\n"
                            "blocks:\n  - {type: identify, id: i, stimuli: [steel, glas], labels: [x]}\n");
  ASSERT_EQ(p.size(), 1u) << all(p);
  EXPECT_EQ(p[0], dir.file("p.yaml") + ":6:46: block 'i': unknown stimulus 'glas' (did you mean 'glass'?)");
}

TEST(Protocol, PathEscapingTheFolderIsRejectedUnlessAllowed) {
  TempDir dir;
  write_recording(dir, "outside.wav");
  const std::string text = "study: t\nstimuli:\n  a: {file: ../outside.wav}\n"
                           "blocks:\n  - {type: identify, stimuli: [a], labels: [x]}\n";
  const std::string path = dir.write("sub/p.yaml", text);
  auto p = ms::check_protocol_file(path).problems;
  ASSERT_EQ(p.size(), 1u) << all(p);
  EXPECT_EQ(p[0].rfind(path + ":3:13: stimulus 'a': path '../outside.wav' is outside", 0), 0u) << p[0];
  ms::ValidateOptions o;
  o.allow_outside = true;
  EXPECT_TRUE(ms::check_protocol_file(path, o).problems.empty());
}

TEST(Protocol, MissingFileIsReported) {
  TempDir dir;
  const auto p = check(dir, "study: t\nstimuli:\n  a: {file: nope.wav}\n"
                            "blocks:\n  - {type: identify, stimuli: [a], labels: [x]}\n");
  ASSERT_EQ(p.size(), 1u) << all(p);
  EXPECT_EQ(p[0], dir.file("p.yaml") + ":3:13: stimulus 'a': file 'nope.wav' does not exist");
}

TEST(Protocol, UnreadablePathIsReportedNotThrown) {
  TempDir dir;
  const std::string name(300, 'x');  // longer than any file system allows for one name
  const auto p = check(dir, "study: t\nstimuli:\n  a: {file: " + name + ".wav}\n"
                            "blocks:\n  - {type: identify, stimuli: [a], labels: [x]}\n");
  ASSERT_EQ(p.size(), 1u) << all(p);
  EXPECT_EQ(p[0].rfind(dir.file("p.yaml") + ":3:13: stimulus 'a': file '" + name + ".wav' cannot be read: ", 0), 0u)
      << p[0];
}

TEST(Protocol, DuplicateIdsAreReported) {
  TempDir dir;
  const auto p = check(dir, kHead + "blocks:\n  - {type: ab, id: x, pairs: [[a, b]]}\n"
                                    "  - {type: ab, id: x, pairs: [[b, a]]}\n");
  ASSERT_EQ(p.size(), 1u) << all(p);
  EXPECT_EQ(p[0], dir.file("p.yaml") + ":9:20: duplicate block id 'x' (first at " + dir.file("p.yaml") + ":8:20)");
}

TEST(Protocol, EmptyBlocksAreReported) {
  TempDir dir;
  const auto p = check(dir, kHead + "blocks:\n  - {type: ab, id: x}\n  - {type: mushra, id: m, reference: a}\n"
                                    "  - {type: identify, id: i, stimuli: [a]}\n");
  ASSERT_EQ(p.size(), 3u) << all(p);
  EXPECT_EQ(p[0], dir.file("p.yaml") + ":8:5: block 'x': no pairs");
  EXPECT_EQ(p[1], dir.file("p.yaml") + ":9:5: block 'm': no conditions");
  EXPECT_EQ(p[2], dir.file("p.yaml") + ":10:5: block 'i': identify needs 'labels' (the answer alternatives)");
}

TEST(Protocol, MushraWithoutReference) {
  TempDir dir;
  const auto p = check(dir, kHead + "blocks:\n  - {type: mushra, id: m, conditions: [a]}\n");
  ASSERT_EQ(p.size(), 1u) << all(p);
  EXPECT_TRUE(has(p, ":8:5: block 'm': MUSHRA needs a 'reference'")) << all(p);
}

TEST(Protocol, ThreeProblemsAreAllReported) {
  TempDir dir;
  const auto p = check(dir, kHead + "blocks:\n  - {type: ab, id: x, pairs: [[a, c]]}\n"
                                    "  - {type: abb, id: y}\n"
                                    "  - {type: ab, id: x, pairs: [[a, b]]}\n");
  ASSERT_EQ(p.size(), 3u) << all(p);
  EXPECT_TRUE(has(p, ":8:35: block 'x': unknown stimulus 'c'")) << all(p);
  EXPECT_TRUE(has(p, ":9:12: unknown block type 'abb' (did you mean 'ab'?)")) << all(p);
  EXPECT_TRUE(has(p, ":10:20: duplicate block id 'x'")) << all(p);
}

TEST(Protocol, UnknownKeyInBlockIsReportedAndOthersStillChecked) {
  TempDir dir;
  const auto p = check(dir, kHead + "blocks:\n  - {type: ab, id: x, pairz: [[a, b]]}\n"
                                    "  - {type: ab, id: y, pairs: [[a, q]]}\n");
  ASSERT_EQ(p.size(), 2u) << all(p);
  EXPECT_TRUE(has(p, ":8:23: unknown key 'blocks[0].pairz' (did you mean 'pairs'?)")) << all(p);
  EXPECT_TRUE(has(p, "unknown stimulus 'q'")) << all(p);
}

TEST(Protocol, DeriveCycleAndUnknownDerive) {
  TempDir dir;
  const auto p = check(dir, "study: t\nstimuli:\n  a: {derive: b, lowpass_hz: 3500}\n"
                            "  b: {derive: a, lowpass_hz: 3500}\n  c: {derive: zz, lowpass_hz: 100}\n"
                            "blocks:\n  - {type: identify, stimuli: [a], labels: [x]}\n");
  EXPECT_TRUE(has(p, ":3:3: stimulus 'a': derive cycle")) << all(p);
  EXPECT_TRUE(has(p, ":5:15: stimulus 'c' derives from unknown stimulus 'zz'")) << all(p);
}

TEST(Protocol, ParamsetOverrideErrorsPointAtTheProtocol) {
  TempDir dir;
  const std::string path = std::string(MODALSTUDY_SOURCE_DIR) + "/protocols/demo.yaml";
  const std::string text =
      "study: t\nstimuli:\n  s: {paramset: " + std::string(MODALSTUDY_SOURCE_DIR) +
      "/stimuli/bar/sterling-steel.yaml, set: {duration_s: -1}}\nblocks:\n  - {type: identify, stimuli: [s], labels: [x]}\n";
  const auto p = check(dir, text, true);
  ASSERT_EQ(p.size(), 1u) << all(p);
  // At the override's value: line 3, the column of "-1".
  const std::size_t line3 = text.find("  s: {");
  const std::string column = std::to_string(text.find("-1") - line3 + 1);
  EXPECT_TRUE(has(p, dir.file("p.yaml") + ":3:" + column + ": stimulus 's': duration_s: must be greater than 0")) << all(p);
}

TEST(Protocol, DemoValidatesWithZeroProblems) {
  const auto c = ms::check_protocol_file(std::string(MODALSTUDY_SOURCE_DIR) + "/protocols/demo.yaml");
  EXPECT_TRUE(c.problems.empty()) << all(c.problems);
  ASSERT_TRUE(c.protocol);
  std::set<ms::BlockType> types;
  for (const auto& b : c.protocol->blocks) types.insert(b.type);
  EXPECT_EQ(types.size(), ms::block_type_names().size());  // every block type is shown
}

TEST(Schedule, ReproducibleAndParticipantDependent) {
  const auto pr = ms::load_protocol(std::string(MODALSTUDY_SOURCE_DIR) + "/protocols/demo.yaml");
  auto flat = [](const ms::Schedule& s) {
    std::vector<std::string> v;
    for (const auto& t : s.trials) {
      std::string line = t.block_id + "/" + std::to_string(t.index);
      for (const auto& n : t.stimuli) line += " " + n;
      v.push_back(line);
    }
    return v;
  };
  const auto a1 = ms::make_schedule(pr, "P01"), a2 = ms::make_schedule(pr, "P01");
  const auto b = ms::make_schedule(pr, "P02");
  EXPECT_EQ(flat(a1), flat(a2));
  EXPECT_EQ(a1.block_order, a2.block_order);
  EXPECT_NE(flat(a1), flat(b));
  EXPECT_NE(a1.block_order, b.block_order);  // different Latin-square rows
  ASSERT_FALSE(a1.trials.empty());
  // Training block flagged, MUSHRA screen holds hidden reference + condition + derived + 2 anchors.
  bool training = false;
  for (const auto& t : a1.trials) {
    training |= t.training;
    if (t.type == ms::BlockType::mushra) {
      EXPECT_EQ(t.reference, "full");
      EXPECT_EQ(t.stimuli.size(), 5u);
    }
  }
  EXPECT_TRUE(training);
}

TEST(Schedule, LatinSquareRowsAndColumnsArePermutations) {
  for (std::size_t n : {1u, 2u, 3u, 4u, 5u, 6u, 7u}) {
    const auto sq = ms::latin_square(n);
    ASSERT_EQ(sq.size(), n);
    for (std::size_t i = 0; i < n; ++i) {
      std::set<std::size_t> row(sq[i].begin(), sq[i].end()), col;
      for (std::size_t r = 0; r < n; ++r) col.insert(sq[r][i]);
      EXPECT_EQ(row.size(), n);
      EXPECT_EQ(col.size(), n);
      EXPECT_LT(*row.rbegin(), n);
    }
    if (n % 2 == 0) {  // Williams: every ordered neighbour pair exactly once
      std::set<std::pair<std::size_t, std::size_t>> seen;
      for (const auto& row : sq)
        for (std::size_t c = 0; c + 1 < n; ++c) EXPECT_TRUE(seen.insert({row[c], row[c + 1]}).second);
    }
  }
}

TEST(Schedule, FisherYatesIsAPermutationAndSeeded) {
  std::vector<int> v(20);
  for (int i = 0; i < 20; ++i) v[static_cast<std::size_t>(i)] = i;
  auto w = v, x = v;
  std::mt19937_64 r1(5), r2(5);
  ms::fisher_yates(w, r1);
  ms::fisher_yates(x, r2);
  EXPECT_EQ(w, x);
  EXPECT_NE(w, v);
  std::sort(w.begin(), w.end());
  EXPECT_EQ(w, v);
  EXPECT_EQ(ms::latin_square_row("P07", 4), 3u);
}

TEST(Protocol, SliderKeysMustLoadOnTheirParameterSet) {
  TempDir dir;
  const std::string text = "study: t\nstimuli:\n  s: {paramset: " + std::string(MODALSTUDY_SOURCE_DIR) +
                           "/stimuli/bar/sterling-steel.yaml}\nblocks:\n  - type: adjust\n    paramset: s\n"
                           "    sliders:\n      - {key: duration_z, min: 0.1, max: 2}\n";
  const auto p = check(dir, text, true);
  ASSERT_EQ(p.size(), 2u) << all(p);  // min and max
  EXPECT_TRUE(has(p, dir.file("p.yaml") + ":8:15: block 'adjust-1': 'duration_z' = 0.100000 on stimulus 's': "
                                          "unknown key 'duration_z' (did you mean 'duration_s'?)")) << all(p);
}
