// Every shipped parameter set parses, and the resonator bank renders it within 60 dB SNR of the
// double-precision closed form over its whole duration.
#include <gtest/gtest.h>

#include <filesystem>

#include "support/test_util.hpp"
#include "synthesis/output_level.hpp"
#include "synthesis/paramset.hpp"
#include "synthesis/reference_renderer.hpp"
#include "synthesis/resonator_bank.hpp"
#include "synthesis/stimulus.hpp"

using namespace ms;
namespace fs = std::filesystem;

TEST(ShippedStimuli, BankWithin60dBOfClosedForm) {
  std::vector<fs::path> sets;
  for (const auto& e : fs::recursive_directory_iterator(fs::path(MODALSTUDY_SOURCE_DIR) / "stimuli"))
    if (e.path().extension() == ".yaml") sets.push_back(e.path());
  ASSERT_GE(sets.size(), 22u);  // every library material on two reference objects, plus examples
  for (const auto& path : sets) {
    const ParamSet p = load_paramset(path.string());
    std::vector<std::string> warnings;
    const ModalModel model = audible_model(p, warnings);
    const std::size_t frames = std::size_t(std::llround(p.duration_s * p.sample_rate_hz));
    const auto ref = render_reference(model, p.excitation, p.sample_rate_hz, frames);
    const auto bank = render_bank(model, p.excitation, p.sample_rate_hz, frames);
    const double snr = test::snr_db(ref, bank);
    EXPECT_GT(snr, 60.0) << path;
    RecordProperty(path.filename().string(), std::to_string(snr));
  }
}

TEST(ShippedStimuli, EveryMaterialOnTwoObjects) {
  const fs::path root = fs::path(MODALSTUDY_SOURCE_DIR) / "stimuli";
  for (const char* object : {"bar", "plate"}) {
    std::size_t n = 0;
    for (const auto& e : fs::directory_iterator(root / object)) {
      const ParamSet p = load_paramset(e.path().string());
      EXPECT_GT(p.model.modes.size(), 3u) << e.path();
      ++n;
    }
    EXPECT_EQ(n, 11u) << object;
  }
}
