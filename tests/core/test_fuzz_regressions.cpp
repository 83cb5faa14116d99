// The fuzz targets' inputs under GoogleTest: every seed of tests/fuzz/corpus/<target>/ and every input
// a fuzzer once found (tests/fuzz/regressions/<target>/) is accepted or refused with an InputError by
// its reader; another exception fails here, a crash fails the suite.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "fuzz/fuzz_inputs.hpp"

namespace fs = std::filesystem;

namespace {

std::size_t replay(const std::string& target, const std::function<void(std::string_view)>& input) {
  std::size_t files = 0;
  for (const char* kind : {"corpus", "regressions"}) {
    const fs::path dir = fs::path(MODALSTUDY_SOURCE_DIR) / "tests/fuzz" / kind / target;
    if (!fs::is_directory(dir)) continue;
    for (const auto& entry : fs::directory_iterator(dir)) {
      if (!entry.is_regular_file()) continue;
      std::ifstream in(entry.path(), std::ios::binary);
      std::stringstream bytes;
      bytes << in.rdbuf();
      EXPECT_NO_THROW(input(bytes.str())) << entry.path();
      ++files;
    }
  }
  return files;
}

}  // namespace

TEST(FuzzRegressions, ParameterSets) { EXPECT_GE(replay("paramset", ms::fuzz::paramset), 8u); }
TEST(FuzzRegressions, Protocols) { EXPECT_GE(replay("protocol", ms::fuzz::protocol), 3u); }
TEST(FuzzRegressions, Csv) { EXPECT_GE(replay("csv", ms::fuzz::csv), 4u); }
TEST(FuzzRegressions, Wav) { EXPECT_GE(replay("wav", ms::fuzz::wav), 5u); }
TEST(FuzzRegressions, WebMushraConfigs) { EXPECT_GE(replay("webmushra", ms::fuzz::webmushra), 3u); }
