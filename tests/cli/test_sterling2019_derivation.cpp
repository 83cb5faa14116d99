// The synthetic datasets of protocols/sterling2019.yaml are what stimuli/replications/sterling2019/derive.sh
// fits to the "recorded" sounds: re-deriving two cells (the real clave; the plastic rod's stand-in, ten
// rendered strikes) with the built modalstudy gives the same rows of fits.csv and emg-choice.csv, digit
// for digit, and the clave's measured object byte for byte. A change to the stand-ins, the extractor or the estimators that moves
// a fitted law fails here until derive.sh is run again (and the protocol's numbers follow it, which
// Sterling2019StandIns.TheProtocolPlaysTheDerivedLaws checks).
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "support/test_util.hpp"

namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::set<std::string> lines_of(const std::string& text, const std::string& prefix) {
  std::set<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(prefix, 0) == 0) out.insert(line);
  return out;
}

TEST(Sterling2019Derivation, RederivingTwoCellsGivesTheCommittedFiles) {
  const std::string source = MODALSTUDY_SOURCE_DIR, derived = source + "/stimuli/replications/sterling2019/derived/";
  const ms::test::TempDir dir;
  const std::string cmd = "cd '" + source + "' && bash stimuli/replications/sterling2019/derive.sh '" +
                          std::string(MODALSTUDY_BIN) + "' '" + dir.path().string() + "' rod-wood rod-plastic >'" +
                          dir.file("log") + "' 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << slurp(dir.file("log"));
  EXPECT_EQ(slurp(dir.file("object-rod-wood.yaml")), slurp(derived + "object-rod-wood.yaml"));
  for (const std::string cell : {"rod-wood,", "rod-plastic,"}) {
    const std::set<std::string> fits = lines_of(slurp(dir.file("fits.csv")), cell);
    EXPECT_EQ(fits.size(), 5u) << cell;  // emg hybrid and Rayleigh, constant and relative spread; ray
    EXPECT_EQ(fits, lines_of(slurp(derived + "fits.csv"), cell)) << cell;
    EXPECT_EQ(lines_of(slurp(dir.file("emg-choice.csv")), cell), lines_of(slurp(derived + "emg-choice.csv"), cell)) << cell;
  }
}

// Some cells derived over the committed files would leave fits.csv without the others' rows.
TEST(Sterling2019Derivation, SomeCellsAreNotDerivedOverTheCommittedFiles) {
  const std::string source = MODALSTUDY_SOURCE_DIR, derived = source + "/stimuli/replications/sterling2019/derived/";
  const std::string fits = slurp(derived + "fits.csv");
  const ms::test::TempDir dir;
  const std::string cmd = "cd '" + source + "' && bash stimuli/replications/sterling2019/derive.sh '" +
                          std::string(MODALSTUDY_BIN) + "' stimuli/replications/sterling2019/derived/ rod-wood >'" +
                          dir.file("log") + "' 2>&1";
  const int status = std::system(cmd.c_str());
  EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 2);
  const std::string log = slurp(dir.file("log"));
  EXPECT_EQ(std::count(log.begin(), log.end(), '\n'), 1) << log;
  EXPECT_NE(log.find("would drop the other cells' fits"), std::string::npos) << log;
  EXPECT_EQ(slurp(derived + "fits.csv"), fits);
}

// set_protocol_laws.py is how derive.sh puts the fits into the protocol: it rewrites only the damping
// maps of the emg and ray stimuli, so a protocol whose laws drifted comes back byte for byte.
struct Script {
  int exit_code;
  std::string out, err;
};
Script set_protocol_laws(const std::string& derived, const std::string& protocol, const ms::test::TempDir& dir,
                         const std::string& flags = "") {
  const std::string cmd = "python3 '" + std::string(MODALSTUDY_SOURCE_DIR) +
                          "/stimuli/replications/sterling2019/set_protocol_laws.py' '" + derived + "' '" + protocol +
                          "' " + flags + " >'" + dir.file("out") + "' 2>'" + dir.file("err") + "'";
  const int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir.file("out")), slurp(dir.file("err"))};
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

TEST(Sterling2019Derivation, SetProtocolLawsWritesTheDerivedLawsBack) {
  const std::string source = MODALSTUDY_SOURCE_DIR, derived = source + "/stimuli/replications/sterling2019/derived";
  const std::string committed = slurp(source + "/protocols/sterling2019.yaml");
  const ms::test::TempDir dir;
  EXPECT_EQ(set_protocol_laws(derived, source + "/protocols/sterling2019.yaml", dir, "--check").exit_code, 0);

  // One number changed (the clave's EMG), one law swapped (the glass disc's ray dataset).
  std::string drifted = replaced(committed, "set: {damping: {law: hybrid, alpha1: 8.98", "set: {damping: {law: hybrid, alpha1: 1.98");
  const auto ray_glass = drifted.find("damping: {law: rayleigh", drifted.find("  ray-disc-glass:"));
  ASSERT_NE(ray_glass, std::string::npos);
  drifted.replace(ray_glass, drifted.find('}', ray_glass) + 1 - ray_glass, "damping: {law: hybrid, alpha1: 1, alpha2: 2, alpha3: 3}");
  const std::string protocol = dir.write("p.yaml", drifted);
  const Script check = set_protocol_laws(derived, protocol, dir, "--check");
  EXPECT_EQ(check.exit_code, 1);
  EXPECT_EQ(std::count(check.out.begin(), check.out.end(), '\n'), 4) << check.out;  // two lines, each old -> new
  EXPECT_EQ(slurp(protocol), drifted);  // --check writes nothing
  const Script write = set_protocol_laws(derived, protocol, dir);
  EXPECT_EQ(write.exit_code, 0) << write.err;
  EXPECT_EQ(slurp(protocol), committed);
}

TEST(Sterling2019Derivation, SetProtocolLawsRefusesIncompleteFitsAndLeavesTheProtocol) {
  const std::string source = MODALSTUDY_SOURCE_DIR, derived = source + "/stimuli/replications/sterling2019/derived/";
  const ms::test::TempDir dir;
  const std::string fits = slurp(derived + "fits.csv"), choice = slurp(derived + "emg-choice.csv");
  const std::string drifted =
      replaced(slurp(source + "/protocols/sterling2019.yaml"), "set: {damping: {law: hybrid, alpha1: 8.98", "set: {damping: {law: hybrid, alpha1: 1.98");
  const std::string protocol = dir.write("p.yaml", drifted);
  const auto expect_refused = [&](const std::string& name, const std::string& fits_csv, const std::string& choice_csv,
                                  const std::string& message) {
    dir.write(name + "/fits.csv", fits_csv);
    dir.write(name + "/emg-choice.csv", choice_csv);
    const Script r = set_protocol_laws(dir.file(name), protocol, dir);
    EXPECT_EQ(r.exit_code, 2) << name;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << name << ": " << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << name << ": " << r.err;
    EXPECT_EQ(slurp(protocol), drifted) << name;
  };
  const auto without = [](const std::string& text, const std::string& line_start) {
    std::string out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
      if (line.rfind(line_start, 0) != 0) out += line + "\n";
    return out;
  };
  expect_refused("no-ray-fit", without(fits, "rod-glass,ray,"), choice, "no ray fit for rod-glass");
  expect_refused("no-cell", without(fits, "disc-plastic,"), without(choice, "disc-plastic,"), "disc-plastic has no derived law");
  expect_refused("not-a-number", replaced(fits, "rod-metal,ray,rayleigh,", "rod-metal,ray,rayleigh,x"), choice,
                 "fits.csv:");
  expect_refused("unknown-law", fits, replaced(choice, "rod-metal,rayleigh,", "rod-metal,power,"), "law 'power'");
  expect_refused("no-columns", "cell,dataset\n", choice, "missing column(s) law, alpha1, alpha2, alpha3");
  expect_refused("no-files", "", "", "emg-choice.csv:1: missing column(s)");
}

}  // namespace
