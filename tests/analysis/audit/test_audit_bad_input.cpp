// Input an audit cannot answer gets a clear AuditError, never a confident wrong answer.
#include <gtest/gtest.h>

#include "analysis/audit/audit.hpp"
#include "analysis/audit/hidden_effect_generator.hpp"

namespace ms::audit {
namespace {

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const AuditError& e) {
    return e.what();
  }
  return "";
}

TEST(AuditBadInput, DifferentSampleRates) {
  HiddenCase hc = generate_hidden_case(5, {}, {});
  hc.recordings[2].sample_rate_hz = 48000;
  const std::string e = error_of([&] { make_audit_data(hc.recordings); });
  EXPECT_NE(e.find("strike3: sample rate 48000 Hz differs from strike1's 44100 Hz"), std::string::npos) << e;
}

TEST(AuditBadInput, Silence) {
  HiddenCase hc = generate_hidden_case(5, {}, {});
  std::fill(hc.recordings[1].samples.begin(), hc.recordings[1].samples.end(), 0.0f);
  const std::string e = error_of([&] { make_audit_data(hc.recordings); });
  EXPECT_EQ(e.rfind("strike2: ", 0), 0u) << e;
  EXPECT_NE(e.find("silent"), std::string::npos) << e;
}

TEST(AuditBadInput, SingleStrike) {
  GeneratorOptions g;
  g.strikes = 1;
  const HiddenCase hc = generate_hidden_case(5, {}, {}, g);
  const AuditData data = make_audit_data(hc.recordings);
  const std::string e = error_of([&] { run_audit(data); });
  EXPECT_NE(e.find("at least 2 strikes"), std::string::npos) << e;
  EXPECT_NE(e.find("got 1"), std::string::npos) << e;
}

TEST(AuditBadInput, ModelOfAnotherObject) {
  const HiddenCase hc = generate_hidden_case(5, {}, {});
  const AuditData data = make_audit_data(hc.recordings);
  // Same object: accepted, and nothing is missing.
  const AuditResult same = run_audit(data, hc.object);
  EXPECT_TRUE(same.named.empty());
  EXPECT_LT(same.gap_before_db, 2.0);
  // Another object: refused with the share of energy its modes account for.
  const HiddenCase other = generate_hidden_case(6, {}, {});
  const std::string e = error_of([&] { run_audit(data, other.object); });
  EXPECT_NE(e.find("do not match the recordings"), std::string::npos) << e;
}

}  // namespace
}  // namespace ms::audit
