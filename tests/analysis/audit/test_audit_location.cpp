// The audit's entry and exit in the library: a parameter set as the baseline (strike gain and contact
// folded into the amplitudes, the sample rate checked) and the reading of where the gap lies.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "analysis/audit/gap_location.hpp"
#include "analysis/audit/given_model.hpp"
#include "analysis/audit/strikes.hpp"
#include "synthesis/excitation.hpp"
#include "synthesis/paramset.hpp"

namespace ms::audit {
namespace {

ParamSet two_modes(const std::string& excitation) {
  return parse_paramset("sample_rate: 44100\nduration_s: 0.5\nmodes:\n"
                        "  - {freq_hz: 440.0, decay_per_s: 6.0, amp: 0.5}\n"
                        "  - {freq_hz: 5200.0, decay_per_s: 20.0, amp: 0.3}\n"
                        "excitation: " + excitation + "\nlevel: {normalize: none}\n",
                        "set.yaml", ".");
}

TEST(AuditGivenModel, FoldsTheStrikeGainAndTheContactIntoTheAmplitudes) {
  const ModalModel impulse = given_model(two_modes("{type: impulse, gain: 2.0}"), "set.yaml", 44100.0);
  ASSERT_EQ(impulse.modes.size(), 2u);
  EXPECT_DOUBLE_EQ(impulse.modes[0].amp, 1.0);
  EXPECT_DOUBLE_EQ(impulse.modes[1].amp, 0.6);

  const ParamSet soft = two_modes("{type: raised_cosine, contact_s: 0.001}");
  const ModalModel contact = given_model(soft, "set.yaml", 44100.0);
  for (std::size_t n = 0; n < 2; ++n) {
    const double factor = std::abs(contact_factor(soft.excitation, soft.model.modes[n].decay_per_s,
                                                  soft.model.modes[n].freq_hz));
    EXPECT_NEAR(contact.modes[n].amp, soft.model.modes[n].amp * factor, 1e-15);
  }
  // Against the raised cosine's spectrum for an undamped mode, |sin(pi f tau)/(pi f tau)| / |1 - (f tau)^2|
  // (the decays, 6 and 20 1/s, move it by up to 1 % near the pulse's spectral zeros).
  auto undamped = [](double f_tau) {
    return std::abs(std::sin(std::numbers::pi * f_tau) / (std::numbers::pi * f_tau)) / std::abs(1.0 - f_tau * f_tau);
  };
  EXPECT_NEAR(contact.modes[0].amp / 0.5, undamped(0.44), 0.01 * undamped(0.44));
  EXPECT_NEAR(contact.modes[1].amp / 0.3, undamped(5.2), 0.02 * undamped(5.2));
}

TEST(AuditGivenModel, ASetAtAnotherRateIsRefusedByName) {
  try {
    given_model(two_modes("{type: impulse}"), "bowl.yaml", 48000.0);
    FAIL() << "accepted a set at another rate";
  } catch (const AuditError& e) {
    EXPECT_STREQ(e.what(), "bowl.yaml: sample rate 44100 Hz differs from the recordings' 48000 Hz");
  }
}

TEST(AuditGapLocation, RanksBandsAndFramesAndAveragesTheMaps) {
  GapLocation where;
  where.band_gap_db = {1.0, 4.0, 2.5, 4.0, 0.5};
  where.time_gap_db = {0.2, 3.0, 7.5, 1.0};
  EXPECT_EQ(worst_bands(where, 3), (std::vector<std::size_t>{1, 3, 2}));  // ties keep band order
  EXPECT_EQ(worst_bands(where, 9).size(), 5u);
  EXPECT_EQ(worst_frame(where), 2u);
  EXPECT_EQ(worst_frame(GapLocation{}), 0u);

  const double nan = std::nan("");
  GapMap a{2, 2, {1.0, nan, 3.0, nan}, 0.0}, b{2, 2, {3.0, nan, -1.0, 2.0}, 0.0};
  const auto mean = mean_gap_map({a, b});  // [band][frame]; diff_db is frame-major
  ASSERT_EQ(mean.size(), 2u);
  EXPECT_DOUBLE_EQ(mean[0][0], 2.0);
  EXPECT_DOUBLE_EQ(mean[0][1], 1.0);
  EXPECT_TRUE(std::isnan(mean[1][0]));
  EXPECT_DOUBLE_EQ(mean[1][1], 2.0);
  EXPECT_TRUE(mean_gap_map({}).empty());
}

}  // namespace
}  // namespace ms::audit
