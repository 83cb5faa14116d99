// protocols/skandalou2017_changepoint.yaml keeps the design of Skandalou & Ireland's third experiment as
// its header describes it: five objects x two methods, each a sweep of Q from 1000 by 200 to 4600 in a
// fixed order, the band-pass sounds at that Q and the sinusoidal ones at D = 1/Q; trials shuffled per
// participant, the sounds within a trial never; and the autopilot's marks reach Fig. 5.4's counts.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <map>
#include <set>

#include "core_fixtures.hpp"
#include "studyapp/core/protocol_validator.hpp"
#include "synthesis/paramset.hpp"

namespace ms {
namespace {

const std::string kProtocol = "skandalou2017_changepoint.yaml";

std::string factor(const StimulusSource& s, const std::string& name) {
  for (const auto& [n, level] : s.factors)
    if (n == name) return level;
  return "";
}

std::string override_value(const StimulusSource& s, const std::string& key) {
  for (const auto& o : s.overrides)
    if (o.rfind(key + "=", 0) == 0) return o.substr(key.size() + 1);
  return "";
}

TEST(ReplicationChangepoint, KeepsTheThesisDesign) {
  const std::string path = std::string(MODALSTUDY_SOURCE_DIR) + "/protocols/" + kProtocol;
  const ProtocolCheck check = check_protocol_file(path);
  ASSERT_TRUE(check.problems.empty()) << check.problems.front();
  const Protocol& p = *check.protocol;
  const Block* b = p.find_block("q-sweep");
  ASSERT_NE(b, nullptr);
  const auto& c = std::get<ChangepointBlock>(b->body);
  EXPECT_EQ(c.parameter, "Q");
  std::vector<double> q;
  for (int v = 1000; v <= 4600; v += 200) q.push_back(v);  // "starting from 1000, increased by 200 up to 4600"
  EXPECT_EQ(c.values, q);
  ASSERT_EQ(c.sweeps.size(), 10u);
  std::set<std::pair<std::string, std::string>> cells;  // object x method
  for (const auto& sweep : c.sweeps) {
    const StimulusSource* first = p.find_stimulus(sweep.front().name);
    ASSERT_NE(first, nullptr);
    const std::string object = factor(*first, "object"), method = factor(*first, "method");
    cells.insert({object, method});
    for (std::size_t i = 0; i < sweep.size(); ++i) {
      const StimulusSource* s = p.find_stimulus(sweep[i].name);
      ASSERT_NE(s, nullptr);
      EXPECT_EQ(factor(*s, "object"), object) << s->name;  // one object and method per sweep
      EXPECT_EQ(factor(*s, "method"), method) << s->name;
      EXPECT_NEAR(1.0 / std::stod(override_value(*s, "damping.loss_factor")), q[i], 1e-6 * q[i]) << s->name;
      if (method == "bandpass") {
        EXPECT_EQ(override_value(*s, "renderer"), "bandpass") << s->name;
        EXPECT_DOUBLE_EQ(std::stod(override_value(*s, "bandpass.q")), q[i]) << s->name;
      } else {
        EXPECT_EQ(method, "sinusoidal");
        EXPECT_EQ(override_value(*s, "phase"), "cosine") << s->name;
      }
    }
  }
  EXPECT_EQ(cells.size(), 10u);  // 5 objects x 2 methods, each once
  // Every sound of a sweep keeps the same modes (the pruning's ranking does not depend on Q)
  const auto modes_of = [&](const std::string& name) {
    const StimulusSource* s = p.find_stimulus(name);
    const ParamSet set = load_paramset(p.base_dir + "/" + s->path, s->overrides);
    std::vector<double> f;
    for (const auto& m : set.model.modes) f.push_back(m.freq_hz);
    return f;
  };
  for (const auto& sweep : c.sweeps) {  // (their damped frequencies move by less than 0.01 % with the decay)
    const auto low = modes_of(sweep.front().name), high = modes_of(sweep.back().name);
    ASSERT_EQ(low.size(), high.size()) << sweep.front().name;
    for (std::size_t m = 0; m < low.size(); ++m) EXPECT_NEAR(low[m], high[m], 1e-4 * high[m]) << sweep.front().name;
  }
  // Trials shuffled per participant, sounds in order within each.
  std::set<std::vector<std::string>> orders;
  for (const char* who : {"P1", "P2", "P3"}) {
    std::vector<std::string> firsts;
    for (const Trial& t : make_schedule(p, who).trials) {
      if (t.type != BlockType::changepoint) continue;
      const auto& sweep = *std::find_if(c.sweeps.begin(), c.sweeps.end(),
                                        [&](const auto& s) { return s.front().name == t.stimuli.front(); });
      ASSERT_EQ(t.stimuli.size(), sweep.size());
      for (std::size_t i = 0; i < sweep.size(); ++i) EXPECT_EQ(t.stimuli[i], sweep[i].name);
      firsts.push_back(t.stimuli.front());
    }
    EXPECT_EQ(firsts.size(), 10u);
    orders.insert(firsts);
  }
  EXPECT_EQ(orders.size(), 3u);
}

TEST(ReplicationChangepoint, AutopilotMarksReachFigure54) {
  test::TempDir dir;
  const AutopilotOptions o = testing::shipped_study(kProtocol, dir);
  ASSERT_TRUE(testing::run_participants_and_export(o, 2, "S", 3, dir.file("out")));
  const auto run = test::run_cli("stats changepoint " + dir.file("out/changepoint.csv") + " --by object --json", dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto j = nlohmann::json::parse(run.out);
  ASSERT_EQ(j["groups"].size(), 6u);  // five objects and all together
  for (const auto& g : j["groups"]) {
    EXPECT_EQ(g["sweeps"], g["group"] == "all" ? 20 : 4) << g["group"];  // 2 participants x 2 methods per object
    ASSERT_EQ(g["counts"].size(), 19u);
    EXPECT_EQ(g["counts"][0]["marks"], 0);  // the first sound has nothing to change from
  }
}

}  // namespace
}  // namespace ms
