// protocol check warns when a MUSHRA condition is the same low-pass `anchors: auto` adds.
#include <gtest/gtest.h>

#include "studyapp/core/protocol_parser.hpp"
#include "studyapp/core/protocol_validator.hpp"

namespace {

std::vector<std::string> warnings_of(const std::string& stimuli, const std::string& conditions) {
  const std::string text = "study: t\ntitle: T\nstimuli:\n  full: {file: a.wav}\n" + stimuli +
                           "blocks:\n  - {type: mushra, id: mu, reference: full, conditions: [" + conditions +
                           "], anchors: auto}\n";
  return ms::protocol_warnings(ms::parse_protocol(text, "p.yaml", "."));
}

}  // namespace

TEST(ProtocolAnchorWarning, ConditionEqualToAnAutomaticAnchorIsNamed) {
  const auto w = warnings_of("  lp35: {derive: full, lowpass_hz: 3500}\n  lp5: {derive: full, lowpass_hz: 5000}\n",
                             "lp35, lp5");
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].rfind("p.yaml:8:", 0), 0u) << w[0];  // where the block names it
  EXPECT_NE(w[0].find("condition 'lp35' is the 3.5 kHz low-pass of 'full'"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("full~lp3500"), std::string::npos) << w[0];
  // 7 kHz too; a low-pass of another stimulus, or without anchors: auto, is fine.
  EXPECT_EQ(warnings_of("  lp7: {derive: full, lowpass_hz: 7000}\n", "lp7").size(), 1u);
  EXPECT_TRUE(warnings_of("  o: {file: b.wav}\n  lpo: {derive: o, lowpass_hz: 3500}\n", "lpo").empty());
}

TEST(ProtocolAnchorWarning, ShippedProtocolsHaveNone) {
  for (const char* name : {"demo.yaml", "vandendoel2002.yaml", "sterling2019.yaml", "ren2013_materials.yaml",
                           "ab_synthesis_methods.yaml"}) {
    const ms::ProtocolCheck c =
        ms::check_protocol_file(std::string(MODALSTUDY_SOURCE_DIR) + "/protocols/" + name, ms::ValidateOptions{});
    EXPECT_TRUE(c.problems.empty()) << name << ": " << (c.problems.empty() ? "" : c.problems[0]);
    EXPECT_TRUE(c.warnings.empty()) << name << ": " << (c.warnings.empty() ? "" : c.warnings[0]);
  }
}
