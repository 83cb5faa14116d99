// The repeatability floor: gain-only copies of one recording leave nothing for repetition (0 dB), strikes
// that move (per-strike per-mode amplitude jitter) raise it with the jitter, and an effect hidden over
// moving strikes still closes at least half of the held-out gap above the floor.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "analysis/audit/audit.hpp"
#include "analysis/audit/hidden_effect_generator.hpp"
#include "analysis/audit/repeatability_floor.hpp"

namespace ms::audit {
namespace {

AuditResult audit_of(const std::vector<Recording>& recordings) { return run_audit(make_audit_data(recordings)); }

HiddenCase jittered_case(std::uint64_t seed, const std::vector<std::string>& effects, const std::vector<double>& strengths,
                         double jitter_db) {
  GeneratorOptions opt;
  opt.amplitude_jitter_db = jitter_db;
  return generate_hidden_case(seed, effects, strengths, opt);
}

TEST(AuditFloor, ShareIsTheImprovementOverTheGapAboveTheFloor) {
  EXPECT_DOUBLE_EQ(share_above_floor(1.0, 3.0, 1.0), 0.5);
  EXPECT_DOUBLE_EQ(share_above_floor(1.0, 1.0, 1.0), 0.0);  // nothing above the floor
}

TEST(AuditFloor, SharedResidualIsResolvedBeyondTwoStandardErrors) {
  // The best model of the others beats the fold model by 1, 2, 3 dB: mean 2, standard error 1 / sqrt(3).
  RepeatabilityFloor clear;
  clear.strike_gap_db = {2.0, 3.0, 4.0};
  clear.strike_best_db = {1.0, 1.0, 1.0};
  const SharedResidual shared = shared_residual(clear);
  EXPECT_DOUBLE_EQ(shared.mean_db, 2.0);
  EXPECT_NEAR(shared.standard_error_db, 1.0 / std::sqrt(3.0), 1e-12);
  EXPECT_TRUE(shared.resolved());
  // Differences that scatter around zero: the others' residual is their scatter.
  RepeatabilityFloor within;
  within.strike_gap_db = {1.1, 0.9, 1.05, 0.98};
  within.strike_best_db = {1.0, 1.0, 1.0, 1.0};
  EXPECT_NEAR(shared_residual(within).mean_db, 0.0075, 1e-12);
  EXPECT_FALSE(shared_residual(within).resolved());
  EXPECT_FALSE(shared_residual(RepeatabilityFloor{}).resolved());
  // Consistent but under the resolution: the plain model's own imperfection on clean strikes.
  RepeatabilityFloor tiny;
  tiny.strike_gap_db = {1.02, 1.03, 1.02};
  tiny.strike_best_db = {1.0, 1.0, 1.0};
  EXPECT_FALSE(shared_residual(tiny).resolved());
}

TEST(AuditFloor, GainOnlyCopiesOfOneRecordingHaveNoFloor) {
  // The kits' "velocity layers": one strike scaled by -9, -6, -3, -1 and 0 dB; the strike has a room
  // tail the plain model lacks, so the model has a gap the floor does not share.
  const HiddenCase hc = generate_hidden_case(31, {"reverberation"}, {0.8});
  std::vector<Recording> copies;
  for (double db : {-9.0, -6.0, -3.0, -1.0, 0.0}) {
    Recording r = hc.recordings.front();
    r.name = "copy" + std::to_string(copies.size() + 1);
    for (float& v : r.samples) v = float(double(v) * std::pow(10.0, db / 20.0));
    copies.push_back(r);
  }
  const AuditResult r = audit_of(copies);
  std::printf("gain-only copies: floor %.4f dB, held-out gap %.3f -> %.3f dB, named %zu\n", r.floor_db,
              r.cv_gap_before_db, r.cv_gap_after_db, r.named.size());
  EXPECT_LT(r.floor_db, 0.02);
  ASSERT_EQ(r.strike_floor_db.size(), 5u);
  EXPECT_GT(r.cv_gap_before_db, r.floor_db + 0.5);  // the model's own gap lies above it
  EXPECT_NEAR(r.share_above_floor, (r.cv_gap_before_db - r.cv_gap_after_db) / (r.cv_gap_before_db - r.floor_db), 1e-12);
  ASSERT_EQ(r.strike_cv_gap_before_db.size(), 5u);
  double sum = 0.0;
  for (double g : r.strike_cv_gap_before_db) sum += g;
  EXPECT_NEAR(sum / 5.0, r.cv_gap_before_db, 1e-9);
}

TEST(AuditFloor, GrowsWithTheStrikeToStrikeAmplitudeJitter) {
  for (std::uint64_t seed : {31u, 32u, 33u}) {
    double previous = -1.0;
    for (double jitter_db : {0.0, 1.0, 3.0}) {
      const AuditResult r = audit_of(jittered_case(seed, {}, {}, jitter_db).recordings);
      std::string named;
      for (const auto& n : r.named) named += " " + n.effect;
      std::printf("seed %llu jitter %.0f dB: floor %.3f dB, held-out gap %.3f -> %.3f dB (shared beyond the model "
                  "%.3f +- %.3f), named:%s\n",
                  (unsigned long long)seed, jitter_db, r.floor_db, r.cv_gap_before_db, r.cv_gap_after_db,
                  r.left_shared.mean_db, r.left_shared.standard_error_db, named.empty() ? " none" : named.c_str());
      // Nothing hidden: the strikes share nothing resolved beyond the plain model (jitter is independent per
      // strike; the model's own imperfection stays under the resolution).
      if (jitter_db > 0.0) EXPECT_FALSE(r.left_shared.resolved()) << seed << " " << jitter_db;
      EXPECT_GT(r.floor_db, previous + (jitter_db > 0.0 ? 0.2 : -1.0)) << seed << " " << jitter_db;
      if (jitter_db == 0.0) EXPECT_LT(r.floor_db, 0.1) << seed;
      previous = r.floor_db;
    }
  }
}

// A strong contact: the model's residuals follow each strike's contact, so the others' residuals do not
// carry over and the floor stays at or under the final model's held-out gap.
TEST(AuditFloor, AStrongContactDoesNotLiftTheFloorAboveTheModel) {
  const AuditResult r = audit_of(generate_hidden_case(77, {"contact_duration"}, {1.0}).recordings);
  std::printf("contact_duration(1.0): floor %.3f dB, held-out gap %.3f -> %.3f dB, share %.2f\n", r.floor_db,
              r.cv_gap_before_db, r.cv_gap_after_db, r.share_above_floor);
  ASSERT_FALSE(r.named.empty());
  EXPECT_EQ(r.named.front().effect, "contact_duration");
  EXPECT_LE(r.floor_db, r.cv_gap_after_db + 1e-12);
}

TEST(AuditFloor, AnEffectHiddenOverMovingStrikesHalvesTheGapAboveTheFloor) {
  struct Case {
    std::uint64_t seed;
    const char* effect;
    double strength;
  };
  for (const Case& c : {Case{41, "noise_floor", 0.6}, Case{42, "reverberation", 0.6}, Case{43, "damping_law", 0.6},
                        Case{44, "mode_doublet", 0.6}}) {
    const AuditResult r = audit_of(jittered_case(c.seed, {c.effect}, {c.strength}, 2.0).recordings);
    std::string named;
    for (const auto& n : r.named) named += " " + n.effect + "(" + std::to_string(n.share_above_floor) + ")";
    std::printf("seed %llu %s(%.1f) over 2 dB jitter: floor %.3f dB, held-out gap %.3f -> %.3f dB, share above "
                "the floor %.2f, named:%s\n",
                (unsigned long long)c.seed, c.effect, c.strength, r.floor_db, r.cv_gap_before_db, r.cv_gap_after_db,
                r.share_above_floor, named.c_str());
    ASSERT_FALSE(r.named.empty()) << c.effect;
    EXPECT_EQ(r.named.front().effect, c.effect);
    EXPECT_GE(r.share_above_floor, 0.5) << c.effect;
    EXPECT_GT(r.floor_db, 0.3) << c.effect;  // the jitter is a floor no effect closes
    EXPECT_LE(r.floor_db, r.cv_gap_after_db + 1e-12) << c.effect;  // the final model is one model of the others
  }
}

}  // namespace
}  // namespace ms::audit
