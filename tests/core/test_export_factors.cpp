// The whole path of an identification-and-rating study: protocol with `truth:` and `factors:` ->
// autopilot sessions -> export (truth, correct, one column per factor, session, autopilot) ->
// `stats confusion --truth truth` and `stats anova --within dataset,shape,material` on the exported files.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <map>
#include <set>

#include "synthesis/tidy_csv.hpp"
#include "studyapp/core/autopilot.hpp"
#include "studyapp/core/export.hpp"
#include "studyapp/core/protocol_parser.hpp"
#include "studyapp/core/tidy_tables.hpp"
#include "core_fixtures.hpp"
#include "support/test_util.hpp"

using namespace ms;

namespace {

// 2 datasets x 2 shapes x 2 materials, named <dataset>-<shape>-<material>: one- or two-mode sounds.
std::string write_factorial_study(const test::TempDir& dir) {
  std::string stimuli;
  for (const char* ds : {"emg", "ray"})
    for (const char* shape : {"disc", "rod"})
      for (const char* mat : {"metal", "wood"}) {
        const double f = (std::string(shape) == "disc" ? 500.0 : 1500.0) * (std::string(ds) == "emg" ? 1.0 : 1.1);
        const double d = std::string(mat) == "metal" ? 3.0 : 40.0;
        const std::string name = std::string(ds) + "-" + shape + "-" + mat;
        dir.write("sets/" + name + ".yaml", "sample_rate: 44100\nduration_s: 0.4\nmodes:\n  - {freq_hz: " +
                                                std::to_string(f) + ", decay_per_s: " + std::to_string(d) +
                                                ", amp: 0.5}\nexcitation: {type: impulse}\nlevel: {normalize: none}\n");
        stimuli += "  " + name + ":\n    paramset: sets/" + name + ".yaml\n    truth: {shape: " + shape +
                   ", material: " + mat + "}\n    factors: {dataset: " + ds + ", shape: " + shape + ", material: " +
                   mat + "}\n";
      }
  const std::string all = "[emg-disc-metal, emg-disc-wood, emg-rod-metal, emg-rod-wood, ray-disc-metal, ray-disc-wood, "
                          "ray-rod-metal, ray-rod-wood]";
  return dir.write("study.yaml", "study: fact\ntitle: Factorial\nsample_rate: 44100\nseed: 5\nstimuli:\n" + stimuli +
                                     "blocks:\n"
                                     "  - {type: identify, id: shape, stimuli: " + all + ", labels: [disc, rod]}\n"
                                     "  - {type: identify, id: material, stimuli: " + all + ", labels: [metal, wood]}\n"
                                     "  - type: rating\n    id: ratings\n    stimuli: " + all + "\n"
                                     "    attributes: [{name: duration, points: 7}, {name: pitch, points: 7}]\n");
}

}  // namespace

TEST(ExportFactors, AutopilotToConfusionAndAnova) {
  test::TempDir dir;
  AutopilotOptions o;
  o.protocol_path = write_factorial_study(dir);
  o.db_path = dir.file("r.sqlite");
  ASSERT_TRUE(ms::testing::run_participants_and_export(o, 6, "L", 10, dir.file("out")));

  // identify.csv: the truth is the label (not the stimulus name), correct compares the answer with it.
  const TidyCsv id = TidyCsv::read(dir.file("out/identify.csv"));
  for (const char* c : {"session", "autopilot", "stimulus", "truth", "response", "correct", "dataset", "shape",
                        "material"})
    EXPECT_TRUE(id.has_column(c)) << c;
  ASSERT_EQ(id.rows(), 6u * 16u);
  std::size_t correct = 0;
  for (std::size_t r = 0; r < id.rows(); ++r) {
    const std::string stim = id.cell(r, id.column("stimulus")), block = id.cell(r, id.column("block"));
    const std::string truth = id.cell(r, id.column("truth"));
    EXPECT_EQ(truth, id.cell(r, id.column(block == "shape" ? "shape" : "material"))) << stim;
    EXPECT_EQ(stim, id.cell(r, id.column("dataset")) + "-" + id.cell(r, id.column("shape")) + "-" +
                        id.cell(r, id.column("material")));
    EXPECT_EQ(id.cell(r, id.column("correct")), truth == id.cell(r, id.column("response")) ? "1" : "0");
    EXPECT_EQ(id.cell(r, id.column("autopilot")), "1");
    correct += id.cell(r, id.column("correct")) == "1";
  }
  EXPECT_GT(correct, 0u);  // the names never equal the labels: before `truth` every row was 0

  // stats confusion on the export: the diagonal counts the correct answers of the material block.
  const auto conf = test::run_cli("stats confusion " + dir.file("out/identify.csv") +
                                      " --truth truth --response response --where block=material --json", dir);
  ASSERT_EQ(conf.exit_code, 0) << conf.err;
  const auto cj = nlohmann::json::parse(conf.out);
  ASSERT_EQ(cj["labels"], nlohmann::json({"metal", "wood"}));
  std::size_t material_correct = 0;
  for (std::size_t r = 0; r < id.rows(); ++r)
    material_correct += id.cell(r, id.column("block")) == "material" && id.cell(r, id.column("correct")) == "1";
  EXPECT_EQ(cj["counts"][0][0].get<std::size_t>() + cj["counts"][1][1].get<std::size_t>(), material_correct);

  // stats anova on the ratings: 2 x 2 x 2 within, 6 listeners -> df 1/5 for every effect.
  const auto an = test::run_cli("stats anova " + dir.file("out/rating.csv") +
                                    " --dv value --subject participant --within dataset,shape,material"
                                    " --where attribute=pitch --json", dir);
  ASSERT_EQ(an.exit_code, 0) << an.err;
  const auto aj = nlohmann::json::parse(an.out);
  EXPECT_EQ(aj["n_subjects"], 6);
  ASSERT_EQ(aj["effects"].size(), 7u);
  std::set<std::string> names;
  for (const auto& e : aj["effects"]) {
    names.insert(e["effect"].get<std::string>());
    EXPECT_EQ(e["df1"], 1.0);
    EXPECT_EQ(e["df2"], 5.0);
  }
  EXPECT_TRUE(names.count("dataset:shape:material"));

  // Every session is one autopilot session: --exclude-autopilot leaves nothing, and says so.
  const auto none = test::run_cli("stats confusion " + dir.file("out/identify.csv") +
                                      " --truth truth --response response --exclude-autopilot", dir);
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_NE(none.err.find("no rows left after --exclude-autopilot"), std::string::npos) << none.err;
}

TEST(ExportFactors, ShippedReplicationsStateTruthAndFactors) {
  const Protocol s = load_protocol(std::string(MODALSTUDY_SOURCE_DIR) + "/protocols/sterling2019.yaml");
  std::size_t named = 0;
  for (const Block& b : s.blocks) {
    const auto* ib = std::get_if<IdentifyBlock>(&b.body);
    if (!ib) continue;
    for (const StimulusRef& ref : ib->stimuli) {
      const StimulusSource* st = s.find_stimulus(ref.name);
      ASSERT_NE(st, nullptr);
      // <dataset>-<shape>-<material>; "metal" is the label of Sterling's steel.
      const std::string shape = ref.name.substr(4, ref.name.find('-', 4) - 4);
      const std::string material = ref.name.substr(ref.name.rfind('-') + 1);
      EXPECT_EQ(identify_truth(st, ref.name, b), b.id == "shape" ? shape : material) << b.id << " " << ref.name;
      ASSERT_EQ(st->factors.size(), 3u) << ref.name;
      EXPECT_EQ(st->factors[0], (std::pair<std::string, std::string>{"dataset", ref.name.substr(0, 3)}));
      ++named;
    }
  }
  EXPECT_EQ(named, 2u + 40u + 40u);
  const Protocol r = load_protocol(std::string(MODALSTUDY_SOURCE_DIR) + "/protocols/ren2013_materials.yaml");
  for (const StimulusSource& st : r.stimuli) {
    ASSERT_EQ(st.truth.size(), 1u) << st.name;
    EXPECT_EQ(st.truth[0].second, st.name.substr(0, st.name.find('-')));
  }
}
