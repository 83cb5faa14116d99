// The audit proven on hidden effects: generated recordings hide zero, one or two effects; the audit
// must name each hidden effect >= 90 % of the time, nothing on >= 90 % of clean cases, and shrink the
// gap by >= 50 % when an effect is present. Prints the confusion matrix.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "analysis/audit/audit.hpp"
#include "analysis/audit/hidden_effect_generator.hpp"
#include "audit_cases.hpp"

namespace ms::test {
namespace {

// The bars: each effect named in >= 90 % of the cases hiding it, nothing named in >= 90 % of clean
// cases, and the held-out gap above the repeatability floor halving in >= 90 % of the cases with an
// effect (the in-sample gap is printed: beside a room or a moving hit point part of it is repetition,
// which no model closes).
constexpr double kNamedBar = 0.9, kQuietBar = 0.9, kGapShrinkBar = 0.9;
// hit_position is held to the same bar: with each strike's amplitudes read with the model's poles fixed
// it was named in 28 of 28 on 19320-19559 and 27 of 27 on 19560-19799 (independent generator: 25 of 26
// and 27 of 27); read from the free fit, beside a room a few modes 5-12 dB off, 77-95 % a range
// (docs/AUDIT_PROOF.md). On this test's range, 26 of 27.

audit::AuditResult audit_case(const CasePlan& plan) {
  const audit::HiddenCase hc = audit::generate_hidden_case(plan.seed, plan.effects, plan.strengths);
  return audit::run_audit(audit::make_audit_data(hc.recordings));
}

void print_case(const CasePlan& plan, const audit::AuditResult& r) {
  std::printf("seed %llu hidden:", (unsigned long long)plan.seed);
  for (std::size_t i = 0; i < plan.effects.size(); ++i) std::printf(" %s(%.2f)", plan.effects[i].c_str(), plan.strengths[i]);
  std::printf(" | gap %.2f -> %.2f | floor %.2f, share above it %.2f, left shared %.2f +- %.2f | named:", r.gap_before_db,
              r.gap_after_db, r.floor_db, r.share_above_floor, r.left_shared.mean_db, r.left_shared.standard_error_db);
  for (const auto& n : r.named) std::printf(" %s", n.effect.c_str());
  std::printf(" | stats:");
  if (!r.rounds.empty())
    for (const auto& c : r.rounds.front())
      std::printf(" %s=%.3g%s(%.2f)", c.effect.c_str(), c.statistic, c.detector_passes ? "*" : "", c.improvement_db);
  std::printf("\n");
  std::fflush(stdout);  // progress of long runs
}

// Threshold tuning run (disabled: run with --gtest_also_run_disabled_tests): every statistic per case.
// AUDIT_TUNING_FIRST / AUDIT_TUNING_COUNT pick the seeds (default 1000, 60; also used: 1100, 80, 3000, 240
// and 3240, 240);
// AUDIT_TUNING_ONLY=effect hides that effect in every case, at strength 0.1 + 0.2 (seed mod 5).
TEST(AuditHidden, DISABLED_AuditTuning) {
  Tally tally;
  const std::size_t first = env_or("AUDIT_TUNING_FIRST", 1000);
  const std::size_t count = env_or("AUDIT_TUNING_COUNT", 60);
  const char* only = std::getenv("AUDIT_TUNING_ONLY");
  for (std::size_t i = 0; i < count; ++i) {
    CasePlan plan = plan_case(first + i, i, true);
    if (only) plan = {first + i, {only}, {0.1 + 0.2 * double((first + i) % 5)}};
    const auto r = audit_case(plan);
    print_case(plan, r);
    tally.add(plan, r);
  }
  tally.print();
  EXPECT_GT(tally.clean, 0);
}

// Seeds 13000-13239: fresh for the generator that hides reverberation as a convolutional room
// (synthesis/room_response, RT60 0.3-1 s, DRR -2..+8 dB) and the reverberation extension that fits
// one (5000-5119, 7000-7159, 8000-8159, 9000-9159, 10000-10239, 11000-11239 and 12000-12239 held out
// earlier versions and are not reused). AUDIT_HELDOUT_FIRST runs the same protocol on another range
// (to check a change on seeds nobody has looked at; 14000-14239, 15000-15239, 15240-15479,
// 15480-15719, 15720-15959, 15960-16199, 16200-16439, 16440-16679, 16680-16919, 16920-17159,
// 17160-17399, 17400-17639, 17640-17879, 17880-18119, 18120-18359, 18360-18599, 18600-18839,
// 18840-19079, 19080-19319, 19320-19559, 19560-19799 and 19800-20039 have
// been).
TEST(AuditHidden, HeldOutSeedsMeetTheBars) {
  Tally tally;
  const auto t0 = std::chrono::steady_clock::now();
  const std::size_t cases = 240;
  const std::size_t first = env_or("AUDIT_HELDOUT_FIRST", 13000);
  for (std::size_t i = 0; i < cases; ++i) {
    const CasePlan plan = plan_case(first + i, i, false);
    const auto r = audit_case(plan);
    if (std::getenv("AUDIT_VERBOSE")) print_case(plan, r);
    tally.add(plan, r);
  }
  tally.print();
  std::printf("%zu cases in %.1f s\n", cases, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  for (const auto& e : planned_effects()) {
    ASSERT_GT(tally.hidden[e], 20) << e;
    EXPECT_GE(double(tally.hit[e]), kNamedBar * tally.hidden[e]) << e;
  }
  EXPECT_GE(double(tally.clean_quiet), kQuietBar * tally.clean);
  EXPECT_GE(double(tally.halved_above_floor), kGapShrinkBar * tally.with_effect);
}

}  // namespace
}  // namespace ms::test
