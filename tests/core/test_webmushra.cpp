// webMUSHRA in and out: configs written from webMUSHRA's documented schema (doc/experimenter.md)
// become protocols that run, and the answers come back in webMUSHRA's result tables.
#include <gtest/gtest.h>

#include <algorithm>

#include "core_fixtures.hpp"
#include "studyapp/core/autopilot.hpp"
#include "studyapp/core/protocol_parser.hpp"
#include "studyapp/core/webmushra_import.hpp"
#include "studyapp/core/webmushra_results.hpp"
#include "support/test_util.hpp"
#include "synthesis/audio_file.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/tidy_csv.hpp"

using namespace ms;

namespace {

// A webMUSHRA root: configs/ beside the audio it names.
struct WebMushraRoot {
  test::TempDir dir;
  WebMushraRoot() {
    for (const char* name : {"ref", "c1", "c2", "c3"}) write_tone(std::string("configs/audio/") + name + ".wav", 44100);
  }
  void write_tone(const std::string& rel, double rate_hz) const {
    Audio a;
    a.sample_rate_hz = rate_hz;
    for (int i = 0; i < 4410; ++i) a.samples.push_back(float(0.3 * std::sin(0.05 * i) * std::exp(-i / 900.0)));
    std::filesystem::create_directories(std::filesystem::path(dir.file(rel)).parent_path());
    write_wav(dir.file(rel), a, SampleFormat::pcm16);
  }
  std::string config(const std::string& pages) const {
    return dir.write("configs/test.yaml", "testname: A test\ntestId: wm_test\nbufferSize: 2048\npages:\n" + pages);
  }
  WebMushraImport import(const std::string& pages) const {
    return import_webmushra(config(pages), dir.file("study.yaml"));
  }
};

const std::string kMushra =
    "  - type: mushra\n    id: m1\n    name: Quality\n    content: <p>Rate &amp; compare</p>\n"
    "    reference: configs/audio/ref.wav\n    createAnchor35: true\n    createAnchor70: true\n"
    "    stimuli:\n      C1: configs/audio/c1.wav\n      C2: configs/audio/c2.wav\n";

// `text` with every line indented by `spaces` more (a page inside a nested pages list).
std::string indented(const std::string& text, int spaces) {
  std::string out;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    out += std::string(std::size_t(spaces), ' ') + text.substr(start, end - start + 1);
    start = end == std::string::npos ? text.size() : end + 1;
  }
  return out;
}

bool has_note(const WebMushraImport& w, const std::string& part) {
  return std::any_of(w.notes.begin(), w.notes.end(), [&](const std::string& n) { return n.find(part) != std::string::npos; });
}

std::string import_error(const WebMushraRoot& root, const std::string& pages) {
  try {
    root.import(pages);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(WebMushraImport, PagesBecomeBlocksOfAProtocolThatValidates) {
  WebMushraRoot root;
  const WebMushraImport w = root.import(
      "  - {type: generic, id: hello, name: Welcome, content: '<p>Hi.</p><br/><p>Headphones, please.</p>'}\n"
      "  - {type: consent, id: agree, name: Consent, mustConsent: true, content: I agree.}\n"
      "  -\n    - random\n" + indented(kMushra, 2) +
      "  - type: paired_comparison\n    id: pc\n    name: Pick\n    reference: configs/audio/ref.wav\n"
      "    stimuli: {C1: configs/audio/c1.wav, C3: configs/audio/c3.wav}\n"
      "  - type: likert_single_stimulus\n    id: nat\n    name: Natural\n"
      "    stimuli: {C1: configs/audio/c1.wav}\n"
      "    response: [{value: no, label: Not natural}, {value: mid, label: So-so}, {value: yes, label: Natural}]\n"
      "  - type: finish\n    name: Done\n    questionnaire:\n"
      "      - {type: text, name: email, label: E-mail}\n"
      "      - {type: likert, name: phones, label: Headphones, response: [{value: closed}, {value: open}]}\n");
  const Protocol p = parse_protocol(w.protocol_yaml, root.dir.file("study.yaml"), root.dir.path().string());
  EXPECT_EQ(p.study, "wm_test");
  EXPECT_EQ(p.title, "A test");
  EXPECT_EQ(p.sample_rate_hz, 44100);
  std::vector<std::string> types;
  for (const Block& b : p.blocks) types.push_back(b.type_name);
  EXPECT_EQ(types, (std::vector<std::string>{"instructions", "instructions", "questionnaire", "mushra", "ab", "rating",
                                             "questionnaire"}));
  EXPECT_EQ(std::get<InstructionsBlock>(p.blocks[0].body).text, "Welcome\n\nHi.\n\nHeadphones, please.");
  EXPECT_EQ(std::get<QuestionnaireBlock>(p.blocks[2].body).questions[0].options, std::vector<std::string>{"I agree"});
  const auto& m = std::get<MushraBlock>(p.blocks[3].body);
  EXPECT_EQ(m.reference->name, "reference");
  EXPECT_TRUE(m.auto_anchors);
  ASSERT_EQ(m.conditions.size(), 2u);
  EXPECT_EQ(m.conditions[0].name, "C1");
  EXPECT_EQ(p.blocks[3].prompt, "Rate & compare");
  const auto& ab = std::get<AbBlock>(p.blocks[4].body);
  EXPECT_EQ(ab.mode, AbMode::preference);
  ASSERT_EQ(ab.pairs.size(), 2u);
  EXPECT_EQ(ab.pairs[1][0].name, "reference");
  EXPECT_EQ(ab.pairs[1][1].name, "C3");
  const auto& rating = std::get<RatingBlock>(p.blocks[5].body);
  EXPECT_EQ(rating.attributes[0].points, 3);
  EXPECT_EQ(rating.attributes[0].low, "Not natural");
  EXPECT_EQ(rating.attributes[0].high, "Natural");
  const auto& q = std::get<QuestionnaireBlock>(p.blocks[6].body);
  EXPECT_EQ(q.questions[1].options, (std::vector<std::string>{"closed", "open"}));
  // Files are written relative to the protocol; the same file under one name is one stimulus.
  EXPECT_EQ(p.find_stimulus("C1")->path, "configs/audio/c1.wav");
  EXPECT_EQ(p.blocks[3].shuffle, "random-1");  // the random group's one page
  EXPECT_FALSE(has_note(w, "random page order"));
  EXPECT_TRUE(has_note(w, "inner labels"));
}

TEST(WebMushraImport, ARandomGroupIsAShuffleGroupUnlessAPageIsNotOneBlock) {
  WebMushraRoot root;
  std::string second = kMushra;
  second.replace(second.find("id: m1"), 6, "id: m2");
  const WebMushraImport w = root.import("  - {type: generic, id: hello, name: Hi, content: Hi.}\n"
                                        "  -\n    - random\n" + indented(kMushra, 2) + indented(second, 2));
  const Protocol p = parse_protocol(w.protocol_yaml, root.dir.file("study.yaml"), root.dir.path().string());
  ASSERT_EQ(p.blocks.size(), 3u);
  EXPECT_EQ(p.blocks[0].shuffle, "");
  EXPECT_EQ(p.blocks[1].shuffle, "random-1");
  EXPECT_EQ(p.blocks[2].shuffle, "random-1");
  EXPECT_FALSE(has_note(w, "random page order"));
  // A nested list inside the group: its pages keep their written order, said in one note.
  const WebMushraImport nested = root.import("  -\n    - random\n" + indented(kMushra, 2) + "    -\n" +
                                             indented(second, 4));
  EXPECT_TRUE(has_note(nested, "random page order not carried over"));
  const Protocol q = parse_protocol(nested.protocol_yaml, root.dir.file("study.yaml"), root.dir.path().string());
  for (const Block& b : q.blocks) EXPECT_EQ(b.shuffle, "");
}

TEST(WebMushraImport, OneAnchorIsTheLowPassedReferenceAndNoneIsNone) {
  WebMushraRoot root;
  std::string one = kMushra, none = kMushra;
  one.replace(one.find("createAnchor70: true"), 20, "createAnchor70: false");
  none.replace(none.find("createAnchor35: true"), 20, "createAnchor35: false");
  none.replace(none.find("createAnchor70: true"), 20, "createAnchor70: false");
  none.replace(none.find("id: m1"), 6, "id: m2");
  const WebMushraImport w = root.import(one + none);
  const Protocol p = parse_protocol(w.protocol_yaml, root.dir.file("study.yaml"), root.dir.path().string());
  const auto& m1 = std::get<MushraBlock>(p.blocks[0].body);
  ASSERT_EQ(m1.anchors.size(), 1u);
  const StimulusSource* anchor = p.find_stimulus(m1.anchors[0].name);
  ASSERT_NE(anchor, nullptr);
  EXPECT_EQ(anchor->kind, StimulusKind::derived);
  EXPECT_EQ(anchor->lowpass_hz, 3500);
  EXPECT_EQ(anchor->derive_from.name, "reference");
  EXPECT_TRUE(std::get<MushraBlock>(p.blocks[1].body).anchors.empty());
}

TEST(WebMushraImport, WhatAProtocolCannotSayIsOneLocatedNoteEach) {
  WebMushraRoot root;
  std::string page = kMushra;
  page += "    showWaveform: true\n    enableLooping: true\n    switchBack: true\n    colour: red\n";
  page += "  - {type: bs1116, id: bs, reference: configs/audio/ref.wav, stimuli: {C1: configs/audio/c1.wav}}\n";
  page += "  - {type: paired_comparison, id: pc, unforced: Cannot tell, reference: configs/audio/ref.wav, "
          "stimuli: {C1: configs/audio/c3.wav}}\n";
  const WebMushraImport w = root.import(page);
  for (const char* part : {"test.yaml:15:19: pages[0].showWaveform", "enableLooping", "switchBack", "colour: not a key of a mushra page",
                           "forced choice", "'C1_pc': 'C1' is another file"})
    EXPECT_TRUE(has_note(w, part)) << part;
  for (const std::string& n : w.notes) EXPECT_EQ(n.find('\n'), std::string::npos) << n;
}

TEST(WebMushraImport, AudioOutsideTheProtocolsFolderIsAllowedExplicitly) {
  WebMushraRoot root;
  const std::string config = root.config(kMushra);
  std::filesystem::create_directories(root.dir.file("protocols"));
  const WebMushraImport w = import_webmushra(config, root.dir.file("protocols/study.yaml"));
  EXPECT_NE(w.protocol_yaml.find("allow_outside: true"), std::string::npos);
  EXPECT_NE(w.protocol_yaml.find("../configs/audio/c1.wav"), std::string::npos);
}

TEST(WebMushraImport, PathsFallBackToTheConfigsFolder) {
  WebMushraRoot root;
  const WebMushraImport w = import_webmushra(
      root.dir.write("configs/local.yaml", "testId: local\npages:\n  - type: likert_single_stimulus\n    id: l\n"
                                           "    stimuli: {A: audio/c1.wav}\n    response: [{value: a}, {value: b}]\n"),
      root.dir.file("configs/study.yaml"));
  EXPECT_NE(w.protocol_yaml.find("{file: audio/c1.wav}"), std::string::npos) << w.protocol_yaml;
}

TEST(WebMushraImport, BadConfigsAreOneLocatedLine) {
  WebMushraRoot root;
  root.write_tone("configs/audio/slow.wav", 22050);
  root.dir.write("configs/audio/text.wav", "not audio");
  const auto wav = [](const std::string& file) {
    return "  - {type: likert_single_stimulus, id: l, stimuli: {A: " + file + "}, response: [{value: a}, {value: b}]}\n";
  };
  const std::vector<std::pair<std::string, std::string>> cases{
      {"  - {type: mushraa, id: x}\n", "test.yaml:5:12: pages[0].type: unknown page type 'mushraa' (did you mean 'mushra'?)"},
      {wav("configs/audio/missing.wav"), "test.yaml:5:56: pages[0].stimuli.A: audio file 'configs/audio/missing.wav' not found"},
      {wav("../../../etc/passwd"), "leaves webMUSHRA's root folder"},
      {wav("/etc/passwd"), "must be a path relative to webMUSHRA's root folder"},
      {wav("https://example.org/a.wav"), "must be a path relative"},
      {wav("configs/audio/text.wav"), "pages[0].stimuli.A:"},
      {wav("configs/audio/c1.wav") + wav("configs/audio/slow.wav"), "sampled at 22050 Hz, the files before it at 44100 Hz"},
      {"  - {type: likert_single_stimulus, id: l, stimuli: {A: configs/audio/c1.wav}, response: [{value: a}]}\n",
       "at least two Likert points"},
      {"  - {type: generic, content: [unclosed\n", "test.yaml:"},
      {"  - 42\n", "expected a page"},
      {"  - {type: finish, questionnaire: [{type: slider, name: s}]}\n", "unknown question type 'slider'"},
      {"  - {type: generic, id: only, content: hi}\n  - {type: bs1116, reference: configs/audio/ref.wav, "
       "stimuli: {A: configs/audio/c1.wav}}\n", ""},  // valid: the bs1116 page is a note
  };
  for (const auto& [pages, expected] : cases) {
    const std::string e = import_error(root, pages);
    if (expected.empty()) {
      EXPECT_EQ(e, "") << pages;
      continue;
    }
    EXPECT_NE(e.find(expected), std::string::npos) << pages << "\n got: " << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  }
  EXPECT_NE(import_error(root, "  - {type: finish, name: Done}\n").find("no page becomes a block"), std::string::npos);
  EXPECT_NE(import_error(root, "  - {type: bs1116, stimuli: {A: configs/audio/c1.wav}}\n").find("missing 'reference'"),
            std::string::npos);
}

TEST(WebMushraResults, AnImportedStudyComesBackInWebMushrasTables) {
  WebMushraRoot root;
  const std::string pages =
      kMushra +
      "  - {type: paired_comparison, id: pc, reference: configs/audio/ref.wav, stimuli: {C1: configs/audio/c1.wav,"
      " C2: configs/audio/c2.wav}}\n"
      "  - {type: likert_single_stimulus, id: nat, stimuli: {C1: configs/audio/c1.wav, C3: configs/audio/c3.wav},"
      " response: [{value: a}, {value: b}, {value: c}]}\n"
      "  - {type: bs1116, id: bs, reference: configs/audio/ref.wav, createAnchor35: true,"
      " stimuli: {C2: configs/audio/c2.wav}}\n"
      "  - {type: finish, questionnaire: [{type: likert, name: phones, label: Phones, response: [{value: closed}]}]}\n";
  const WebMushraImport w = root.import(pages);
  root.dir.write("study.yaml", w.protocol_yaml);
  AutopilotOptions o;
  o.protocol_path = root.dir.file("study.yaml");
  o.db_path = root.dir.file("r.sqlite");
  o.cache_dir = root.dir.file("cache");
  for (int i = 0; i < 2; ++i) {
    o.participant = "P" + std::to_string(i);
    o.seed = 11 + std::uint64_t(i);
    ASSERT_TRUE(run_autopilot(o).finished);
  }
  const ExportSummary s = export_webmushra(o.db_path, root.dir.file("out"));
  EXPECT_EQ(s.tables, (std::vector<std::string>{"bs1116.csv", "lss.csv", "mushra.csv", "paired_comparison.csv"}));
  const TidyCsv mushra = TidyCsv::read(root.dir.file("out/mushra.csv"));
  EXPECT_EQ(mushra.header(), (std::vector<std::string>{"session_test_id", "phones", "session_uuid", "trial_id",
                                                       "rating_stimulus", "rating_score", "rating_time",
                                                       "rating_comment"}));
  ASSERT_EQ(mushra.rows(), 2u * 5u);  // 2 sessions x (2 conditions, hidden reference, 2 anchors)
  std::vector<std::string> names;
  for (std::size_t r = 0; r < mushra.rows(); ++r) {
    EXPECT_EQ(mushra.cell(r, 0), "wm_test");
    EXPECT_EQ(mushra.cell(r, 1), "closed");
    EXPECT_EQ(mushra.cell(r, 3), "m1");
    const double score = mushra.number(r, 5);
    EXPECT_TRUE(score >= 0 && score <= 100);
    if (r < 5) names.push_back(mushra.cell(r, 4));
  }
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"C1", "C2", "anchor35", "anchor70", "reference"}));
  const TidyCsv pc = TidyCsv::read(root.dir.file("out/paired_comparison.csv"));
  ASSERT_EQ(pc.rows(), 4u);
  for (std::size_t r = 0; r < pc.rows(); ++r) {
    EXPECT_EQ(pc.cell(r, pc.column("choice_reference")), "reference");
    const std::string answer = pc.cell(r, pc.column("choice_answer"));
    EXPECT_TRUE(answer == "reference" || answer == pc.cell(r, pc.column("choice_non_reference"))) << answer;
  }
  // BS.1116: one row per condition and session (C2 and the 3.5 kHz anchor webMUSHRA would create), the
  // hidden reference's grade beside the condition's, both on 1.0-5.0.
  const TidyCsv bs = TidyCsv::read(root.dir.file("out/bs1116.csv"));
  EXPECT_EQ(bs.header(), (std::vector<std::string>{"session_test_id", "phones", "session_uuid", "trial_id",
                                                   "rating_reference", "rating_non_reference", "rating_reference_score",
                                                   "rating_non_reference_score", "rating_time", "choice_comment"}));
  ASSERT_EQ(bs.rows(), 2u * 2u);
  std::vector<std::string> graded;
  for (std::size_t r = 0; r < bs.rows(); ++r) {
    EXPECT_EQ(bs.cell(r, bs.column("trial_id")), "bs");
    EXPECT_EQ(bs.cell(r, bs.column("rating_reference")), "reference");
    graded.push_back(bs.cell(r, bs.column("rating_non_reference")));
    for (const char* col : {"rating_reference_score", "rating_non_reference_score"}) {
      const double grade = bs.number(r, bs.column(col));
      EXPECT_TRUE(grade >= 1.0 && grade <= 5.0) << grade;
    }
  }
  std::sort(graded.begin(), graded.end());
  EXPECT_EQ(graded, (std::vector<std::string>{"C2", "C2", "anchor35", "anchor35"}));
  const TidyCsv lss = TidyCsv::read(root.dir.file("out/lss.csv"));
  ASSERT_EQ(lss.rows(), 4u);
  for (std::size_t r = 0; r < lss.rows(); ++r) {
    const double point = lss.number(r, lss.column("stimuli_rating"));
    EXPECT_TRUE(point >= 1 && point <= 3);
  }
}

TEST(WebMushraResults, BlocksWithoutAWebMushraTableAreNamed) {
  test::TempDir dir;
  const std::string protocol = ms::testing::write_small_study(dir);
  AutopilotOptions o;
  o.protocol_path = protocol;
  o.db_path = dir.file("r.sqlite");
  o.cache_dir = dir.file("cache");
  o.participant = "A";
  ASSERT_TRUE(run_autopilot(o).finished);
  const ExportSummary s = export_webmushra(o.db_path, dir.file("out"));
  EXPECT_EQ(s.tables, std::vector<std::string>{"mushra.csv"});
  ASSERT_EQ(s.notices.size(), 1u);
  EXPECT_NE(s.notices[0].find("block 'id' (identify): no webMUSHRA table"), std::string::npos) << s.notices[0];
  // The small study's MUSHRA reference and its 3.5 kHz low-pass are named as webMUSHRA names them.
  const TidyCsv mushra = TidyCsv::read(dir.file("out/mushra.csv"));
  std::vector<std::string> names;
  for (std::size_t r = 0; r < mushra.rows(); ++r) names.push_back(mushra.cell(r, mushra.column("rating_stimulus")));
  EXPECT_NE(std::find(names.begin(), names.end(), "reference"), names.end());
  EXPECT_NE(std::find(names.begin(), names.end(), "anchor35"), names.end());
}
