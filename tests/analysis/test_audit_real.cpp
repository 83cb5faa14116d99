// The audit on real struck metal and wood from Debian's hydrogen-drumkits (skipped when absent):
// the same object struck softly and hard must disagree through contact_duration; a bell struck
// freely and struck muted (held) must disagree through support_damping.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "analysis/audit/audit.hpp"
#include "synthesis/audio_file.hpp"

namespace ms::audit {
namespace {

const std::filesystem::path kKits = "/usr/share/hydrogen/data/drumkits";

std::vector<Recording> load(const std::string& kit, const std::vector<std::string>& files) {
  std::vector<Recording> out;
  for (const auto& f : files) {
    const Audio a = read_audio((kKits / kit / f).string());
    out.push_back({f, a.sample_rate_hz, mono(a)});
  }
  return out;
}

std::vector<std::string> named(const AuditResult& r) {
  std::vector<std::string> n;
  for (const auto& e : r.named) n.push_back(e.effect);
  std::printf("gap %.2f -> %.2f dB, named:", r.gap_before_db, r.gap_after_db);
  for (const auto& e : r.named) std::printf(" %s (%s)", e.effect.c_str(), e.evidence.c_str());
  std::printf("\n");
  return n;
}

bool has(const std::vector<std::string>& v, const char* s) { return std::find(v.begin(), v.end(), s) != v.end(); }

#define REQUIRE_KITS()                                                                                        \
  if (!std::filesystem::exists(kKits / "The Black Pearl 1.0"))                                               \
  GTEST_SKIP() << "hydrogen-drumkits is not installed (apt-get install hydrogen-drumkits) - no real recordings"

TEST(AuditReal, CowbellSoftToHardIsContactDuration) {
  REQUIRE_KITS();
  const auto rec = load("The Black Pearl 1.0", {"Cowbell-Softest.wav", "Cowbell-Soft.wav", "Cowbell-Med.wav",
                                                "Cowbell-Hard.wav", "Cowbell-Hardest.wav"});
  const AuditResult r = run_audit(make_audit_data(rec));
  EXPECT_TRUE(has(named(r), "contact_duration"));
  EXPECT_LT(r.gap_after_db, r.gap_before_db);
}

TEST(AuditReal, ClaveSoftToHardIsContactDuration) {
  REQUIRE_KITS();
  const auto rec = load("Gimme A Hand 1.0", {"Clave-Softest.wav", "Clave-Soft.wav", "Clave-Med.wav", "Clave-Hard.wav",
                                             "Clave-Hardest.wav"});
  const AuditResult r = run_audit(make_audit_data(rec));
  EXPECT_TRUE(has(named(r), "contact_duration"));
  EXPECT_LT(r.gap_after_db, r.gap_before_db);
}

TEST(AuditReal, BellFreeVersusMutedIsSupportDamping) {
  REQUIRE_KITS();
  const auto rec = load("circAfrique v4", {"Kenkeni1 Bell Hit.wav", "Kenkeni1 Bell Mute.wav"});
  const AuditResult r = run_audit(make_audit_data(rec));
  EXPECT_TRUE(has(named(r), "support_damping"));
  EXPECT_LT(r.gap_after_db, r.gap_before_db);
}

}  // namespace
}  // namespace ms::audit
