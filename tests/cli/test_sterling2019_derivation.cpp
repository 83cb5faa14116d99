// The synthetic datasets of protocols/sterling2019.yaml are what stimuli/replications/sterling2019/derive.sh
// fits to the "recorded" sounds: re-deriving two cells (the real clave; the plastic rod's stand-in, ten
// rendered strikes) with the built modalstudy gives the same rows of fits.csv and emg-choice.csv, digit
// for digit, and the clave's measured object byte for byte. A change to the stand-ins, the extractor or the estimators that moves
// a fitted law fails here until derive.sh is run again (and the protocol's numbers follow it, which
// Sterling2019StandIns.TheProtocolPlaysTheDerivedLaws checks).
#include <gtest/gtest.h>

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

}  // namespace
