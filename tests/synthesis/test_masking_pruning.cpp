// Masking-based mode pruning (synthesis/masking_pruning.hpp), Bark maps and the threshold in quiet.
// Expected numbers are worked by hand in the comments; their full digits come from an independent
// transcription of the rule, tests/data/masking_pruning/hand_values.py (Python's math module only).
//
// The 2002 paper (shared/papers/003) reports, for its Fig. 3: "Of the 179 modes of a vase, only 45
// modes survive using a masking method with a_v = 5dB and a playback level of 70dB". Its vase modes
// were never published, so that figure is cited here and not reproduced.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "synthesis/bark.hpp"
#include "synthesis/masking_pruning.hpp"
#include "synthesis/threshold_in_quiet.hpp"

namespace ms {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

ModalModel model_of(std::initializer_list<Mode> modes) {
  ModalModel m;
  m.modes = modes;
  return m;
}

Mode mode(double f, double d, double a) { return Mode{f, d, a, 0.0}; }

TEST(Bark, ZwickerTerhardtAtKnownFrequencies) {
  // 1000 Hz: 13 atan(0.76) + 3.5 atan(0.017778) = 13 * 0.649870 + 3.5 * 0.0177759 = 8.510532.
  EXPECT_NEAR(bark_zwicker_terhardt(1000.0), 8.510531510722, 1e-11);
  // 16 kHz: 13 atan(12.16) + 3.5 atan(4.551) = 13 * 1.488744 + 3.5 * 1.354507 = 24.094448.
  EXPECT_NEAR(bark_zwicker_terhardt(16000.0), 24.094447570808, 1e-11);
  EXPECT_EQ(bark_zwicker_terhardt(0.0), 0.0);
  EXPECT_LT(bark_zwicker_terhardt(999.0), bark_zwicker_terhardt(1000.0));
}

TEST(Bark, WangSekeyGershoAtKnownFrequencies) {
  // 6 asinh(1000/600) = 6 ln(5/3 + sqrt(1 + 25/9)) = 6 ln(5/3 + 1.943651) = 6 * 1.283796 = 7.702774.
  EXPECT_NEAR(bark_wang_sekey_gersho(1000.0), 7.702773976459, 1e-11);
  EXPECT_NEAR(bark_wang_sekey_gersho(600.0), 6.0 * std::log(1.0 + std::sqrt(2.0)), 1e-12);
  EXPECT_EQ(bark_wang_sekey_gersho(0.0), 0.0);
}

TEST(ThresholdInQuiet, TerhardtAtKnownFrequencies) {
  // 1 kHz: 3.64 * 1 - 6.5 e^(-0.6 * 2.3^2) + 0.001 = 3.64 - 6.5 * 0.0418358 + 0.001 = 3.369067.
  EXPECT_NEAR(threshold_in_quiet_db_spl(1000.0), 3.369066525895, 1e-11);
  // 50 Hz: 3.64 * 0.05^-0.8 = 3.64 * 10.98561 = 39.98760, less the dip 6.5 e^(-0.6 * 3.25^2) = 0.01150.
  EXPECT_NEAR(threshold_in_quiet_db_spl(50.0), 39.976107112275, 1e-10);
  // Near 3.3 kHz the dip makes it negative: 3.64 * 3.3^-0.8 - 6.5 + 0.001 * 3.3^4 = -4.9809.
  EXPECT_NEAR(threshold_in_quiet_db_spl(3300.0), 3.64 * std::pow(3.3, -0.8) - 6.5 + 1e-3 * std::pow(3.3, 4), 1e-12);
  EXPECT_LT(threshold_in_quiet_db_spl(3300.0), -4.98);
}

// Case A: mode 0 at 1000 Hz (amp 1, decay 1: P = 1), mode 1 at 1200 Hz (amp 0.1, decay 1: P = 0.01).
//   sum P = 1.01;  L0 = 70 + 10 log10(1/1.01) = 70 - 0.043214 = 69.956786;  L1 = L0 - 20 = 49.956786.
//   z0 = 8.510532, z1 = 9.701852, z1 - z0 = 1.191321 Bark.
//   Mode 1 lies above mode 0 (upper side): slope s0 = 22 - 69.956786/5 = 8.008643 dB/Bark,
//     T1 = 69.956786 - 16 - 8.008643 * 1.191321 = 53.956786 - 9.540861 = 44.415925 < L1: audible,
//     5.540861 dB above it (the threshold in quiet at 1200 Hz, 2.687 dB, is lower).
//   Mode 0 lies below mode 1 (lower side): T0 = 49.956786 - 16 - 25 * 1.191321 = 4.173770 dB,
//     above the threshold in quiet at 1 kHz (3.369 dB): A0 = 69.956786 - 4.173770 = 65.783016.
//   With a_v = 10 dB: T1 = 50.415925 > L1 = 49.956786, so mode 1 is dropped (0.459 dB under).
TEST(MaskingPruning, TwoModesUpperSideMaskingByHand) {
  const ModalModel m = model_of({mode(1000, 1, 1), mode(1200, 1, 0.1)});
  const PruneResult r = prune_modes(m, PruneOptions{});
  EXPECT_NEAR(r.power[0], 1.0, 0);
  EXPECT_NEAR(r.power[1], 0.01, 1e-17);
  EXPECT_NEAR(r.level_db[0], 69.956786262174, 1e-10);
  EXPECT_NEAR(r.level_db[1], 49.956786262174, 1e-10);
  EXPECT_NEAR(r.masking_db[0], 4.173770461705, 1e-10);
  EXPECT_NEAR(r.masking_db[1], 44.415924922532, 1e-10);
  EXPECT_NEAR(r.loudness_db[0], 65.783015800469, 1e-10);
  EXPECT_NEAR(r.loudness_db[1], 5.540861339642, 1e-10);
  EXPECT_EQ(r.kept, (std::vector<std::size_t>{0, 1}));
  EXPECT_TRUE(r.dropped.empty());

  PruneOptions lower_av;
  lower_av.threshold_db = 10.0;
  const PruneResult r10 = prune_modes(m, lower_av);
  EXPECT_NEAR(r10.masking_db[1], 50.415924922532, 1e-10);
  EXPECT_NEAR(r10.loudness_db[1], -0.459138660358, 1e-10);
  EXPECT_EQ(r10.kept, (std::vector<std::size_t>{0}));
  EXPECT_EQ(r10.dropped, (std::vector<std::size_t>{1}));
  EXPECT_EQ(r10.audible, (std::vector<bool>{true, false}));
}

// Which level the 2002 paper normalises. Sec. 2 defines each mode's masker as a narrowband noise of
// power A^2/D ("the power of the mode integrated over time") and shows the levels "normalized to a
// reference playback level (level immediately after impact)". The reading taken here: the playback
// level is the whole model's, and the modes share it in proportion to A^2/D (the maskers the paper
// defines). The other reading, shares of the onset powers A^2, would make two modes of equal amplitude
// equally loud whatever their decays, i.e. it would ignore the masker power the paper gives.
// By hand: A = (1, 1), D = (1, 4) 1/s: P = (1, 0.25), sum 1.25;
//   L0 = 70 + 10 log10(1/1.25) = 69.030899870 dB, L1 = 70 + 10 log10(0.25/1.25) = 63.010299957 dB
//   (onset shares would give 66.989700043 dB for both).
TEST(MaskingPruning, ModesShareThePlaybackLevelByTimeIntegratedPower) {
  const ModalModel m = model_of({mode(1000, 1, 1), mode(3000, 4, 1)});
  const PruneResult r = prune_modes(m, PruneOptions{});
  EXPECT_NEAR(r.level_db[0], 69.030899870, 1e-9);
  EXPECT_NEAR(r.level_db[1], 63.010299957, 1e-9);
  EXPECT_NEAR(r.level_db[0] - r.level_db[1], 10 * std::log10(4.0), 1e-12);
  // The levels' powers add up to the playback level.
  EXPECT_NEAR(10 * std::log10(std::pow(10, r.level_db[0] / 10) + std::pow(10, r.level_db[1] / 10)), 70.0, 1e-12);
}

// Case B: modes 0 and 1 both at 2000 Hz with P = 1, mode 2 at 1500 Hz with P = 0.01.
//   sum P = 2.01; L0 = L1 = 70 - 10 log10(2.01) = 66.968039, L2 = 46.968039.
//   z(2000) = 13.104056, z(1500) = 11.199359: mode 2 is 1.904698 Bark below, on the lower side of
//   both: each masks it at 66.968039 - 16 - 25 * 1.904698 = 3.350597 dB.
//     max: T2 = 3.350597;   sum: T2 = 3.350597 + 10 log10(2) = 6.360897 dB.
//   Modes 0 and 1 share a Bark value (lower side with distance 0): each masks the other at
//   L - a_v = 50.968039, so with max T0 = T1 = 50.968039 and A0 = A1 = 16 dB exactly (= a_v);
//   with sum, mode 2 adds 10^((46.968039 - 16 - s2 * 1.904698)/10), s2 = 22 - 46.968039/5 = 12.606392:
//   6.957 dB, 44 dB down, which lifts T0 by 1.7e-4 dB to 50.968212.
TEST(MaskingPruning, SameBarkMaskersAndMaxVersusSumByHand) {
  const ModalModel m = model_of({mode(2000, 1, 1), mode(2000, 1, 1), mode(1500, 1, 0.1)});
  PruneOptions o;
  const PruneResult rmax = prune_modes(m, o);
  EXPECT_NEAR(rmax.level_db[0], 66.968039425795, 1e-10);
  EXPECT_NEAR(rmax.level_db[2], 46.968039425795, 1e-10);
  EXPECT_NEAR(rmax.masking_db[0], 50.968039425795, 1e-10);
  EXPECT_NEAR(rmax.masking_db[1], 50.968039425795, 1e-10);
  EXPECT_NEAR(rmax.masking_db[2], 3.350596695679, 1e-10);
  EXPECT_NEAR(rmax.loudness_db[0], 16.0, 1e-10);
  o.combine = MaskingCombine::sum;
  const PruneResult rsum = prune_modes(m, o);
  EXPECT_NEAR(rsum.masking_db[2], 6.360896652319, 1e-9);
  EXPECT_NEAR(rsum.masking_db[2] - rmax.masking_db[2], 10.0 * std::log10(2.0), 1e-9);
  EXPECT_NEAR(rsum.masking_db[0], 50.968211866215, 1e-9);
  EXPECT_NEAR(rsum.masking_db[1], 50.968211866215, 1e-9);
  EXPECT_EQ(rsum.kept, (std::vector<std::size_t>{0, 1, 2}));
}

// Case C: mode 1 at 50 Hz with P = 1e-4 beside mode 0 at 1 kHz with P = 1.
//   L1 = 70 + 10 log10(1e-4/1.0001) = 29.999566 dB. Mode 0's masking there (lower side, 8.0166
//   Bark away) is 69.999566 - 16 - 25 * 8.016614 = -146.416 dB: no masking to speak of, but the
//   threshold in quiet at 50 Hz is 39.976 dB > 29.9996, so mode 1 is inaudible.
TEST(MaskingPruning, ThresholdInQuietDropsAnUnmaskedMode) {
  const PruneResult r = prune_modes(model_of({mode(1000, 1, 1), mode(50, 1, 0.01)}), PruneOptions{});
  EXPECT_NEAR(r.level_db[1], 29.999565727231, 1e-10);
  EXPECT_NEAR(r.masking_db[1], -146.415772473619, 1e-9);
  EXPECT_NEAR(r.quiet_db[1], 39.976107112275, 1e-10);
  EXPECT_NEAR(r.loudness_db[1], 29.999565727231 - 39.976107112275, 1e-9);
  EXPECT_EQ(r.kept, (std::vector<std::size_t>{0}));
  EXPECT_EQ(r.dropped, (std::vector<std::size_t>{1}));
}

// A lone mode has nothing masking it (T = -inf) and is heard at the playback level: at 0 dB SPL
// and 1 kHz that is 3.369 dB under the threshold in quiet.
TEST(MaskingPruning, SingleModeIsJudgedByTheThresholdInQuietOnly) {
  PruneOptions o;
  const PruneResult loud = prune_modes(model_of({mode(1000, 3, 0.5)}), o);
  EXPECT_EQ(loud.level_db[0], 70.0);
  EXPECT_EQ(loud.masking_db[0], -kInf);
  EXPECT_EQ(loud.kept, (std::vector<std::size_t>{0}));
  o.playback_db = 0.0;
  const PruneResult quiet = prune_modes(model_of({mode(1000, 3, 0.5)}), o);
  EXPECT_NEAR(quiet.loudness_db[0], -3.369066525895, 1e-11);
  EXPECT_TRUE(quiet.kept.empty());
  EXPECT_TRUE(prune_modes(ModalModel{}, PruneOptions{}).kept.empty());
}

// amp 0: power 0, level -inf, masks nothing, always dropped, and no NaN anywhere.
TEST(MaskingPruning, ZeroAmplitudeIsInaudibleWithoutNaN) {
  for (MaskingCombine c : {MaskingCombine::max, MaskingCombine::sum}) {
    PruneOptions o;
    o.combine = c;
    const PruneResult r =
        prune_modes(model_of({mode(1000, 1, 0), mode(1010, 1, 1), mode(990, 2, 0)}), o);
    EXPECT_EQ(r.level_db[0], -kInf);
    EXPECT_EQ(r.level_db[1], 70.0);
    EXPECT_EQ(r.masking_db[1], -kInf);  // its only neighbours are silent
    EXPECT_EQ(r.kept, (std::vector<std::size_t>{1}));
    EXPECT_EQ(r.dropped, (std::vector<std::size_t>{0, 2}));
    for (const auto* v : {&r.level_db, &r.masking_db, &r.loudness_db})
      for (double x : *v) EXPECT_FALSE(std::isnan(x));
    const PruneResult all_silent = prune_modes(model_of({mode(1000, 1, 0), mode(500, 1, 0)}), o);
    EXPECT_TRUE(all_silent.kept.empty());
    EXPECT_EQ(all_silent.level_db[0], -kInf);
  }
  // The no-masking baselines keep every mode, silent ones last.
  PruneOptions energy;
  energy.method = PruneMethod::energy;
  EXPECT_EQ(prune_modes(model_of({mode(1000, 1, 0), mode(1010, 1, 1)}), energy).kept,
            (std::vector<std::size_t>{1, 0}));
}

// Orderings of three modes (a_v 16, playback 70):
//   mode 0: 1100 Hz, decay 10, amp 1   -> P 0.10, L 61.739 dB; mode 1 masks it from 0.617 Bark below:
//           65.719 - 16 - (22 - 65.719/5) * 0.616776 = 44.256 -> 17.483 dB above.
//   mode 1: 1000 Hz, decay 1,  amp 0.5 -> P 0.25, L 65.719 dB; mode 0 masks it from above:
//           61.739 - 16 - 25 * 0.616776 = 30.320 -> 35.399 dB above.
//   mode 2:   60 Hz, decay 0.5, amp 0.4 -> P 0.32, L 66.791 dB; threshold in quiet 34.549 dB
//           -> 32.242 dB above.
//   naive (amp) 0,1,2; energy (P) 2,1,0; loudness (dB above) 1,2,0.
TEST(MaskingPruning, EachOrderingByHand) {
  const ModalModel m = model_of({mode(1100, 10, 1), mode(1000, 1, 0.5), mode(60, 0.5, 0.4)});
  PruneOptions o;
  o.order = ModeOrder::naive;
  EXPECT_EQ(prune_modes(m, o).kept, (std::vector<std::size_t>{0, 1, 2}));
  o.order = ModeOrder::energy;
  EXPECT_EQ(prune_modes(m, o).kept, (std::vector<std::size_t>{2, 1, 0}));
  o.order = ModeOrder::loudness;
  const PruneResult r = prune_modes(m, o);
  EXPECT_EQ(r.kept, (std::vector<std::size_t>{1, 2, 0}));
  EXPECT_NEAR(r.loudness_db[0], 17.482930569269, 1e-9);
  EXPECT_NEAR(r.loudness_db[1], 35.398789146859, 1e-9);
  EXPECT_NEAR(r.loudness_db[2], 32.242175768089, 1e-9);
  // The baselines order every mode by their own criterion, whatever `order` says.
  for (auto [method, expected] :
       {std::pair{PruneMethod::naive, std::vector<std::size_t>{0, 1, 2}},
        std::pair{PruneMethod::energy, std::vector<std::size_t>{2, 1, 0}},
        std::pair{PruneMethod::loudness, std::vector<std::size_t>{1, 2, 0}}}) {
    PruneOptions b;
    b.method = method;
    b.order = ModeOrder::naive;
    const PruneResult rb = prune_modes(m, b);
    EXPECT_EQ(rb.kept, expected) << to_string(method);
    EXPECT_TRUE(rb.dropped.empty());
  }
}

TEST(MaskingPruning, TiesAreOrderedByIndex) {
  // Equal amps at different frequencies; equal energies 1^2/1 = 2^2/4 = 1.
  const ModalModel m = model_of({mode(500, 1, 1), mode(4000, 4, 2), mode(2000, 1, 1), mode(8000, 4, 2)});
  PruneOptions o;
  o.method = PruneMethod::naive;
  EXPECT_EQ(prune_modes(m, o).kept, (std::vector<std::size_t>{1, 3, 0, 2}));
  o.method = PruneMethod::energy;
  EXPECT_EQ(prune_modes(m, o).kept, (std::vector<std::size_t>{0, 1, 2, 3}));
  // Identical modes at one frequency: identical levels, each masked by the others alike.
  const ModalModel same = model_of({mode(700, 2, 1), mode(700, 2, 1), mode(700, 2, 1)});
  o.method = PruneMethod::masking;
  o.order = ModeOrder::loudness;
  EXPECT_EQ(prune_modes(same, o).kept, (std::vector<std::size_t>{0, 1, 2}));
}

TEST(MaskingPruning, RejectsBadModesNamingTheMode) {
  auto field_of = [](const ModalModel& m) {
    try {
      prune_modes(m, PruneOptions{});
    } catch (const PruneError& e) {
      return e.field() + "@" + std::to_string(e.mode());
    }
    return std::string("no error");
  };
  EXPECT_EQ(field_of(model_of({mode(100, 1, 1), mode(200, 0, 1)})), "decay_per_s@1");
  EXPECT_EQ(field_of(model_of({mode(100, -1, 1)})), "decay_per_s@0");
  EXPECT_EQ(field_of(model_of({mode(100, 1, std::nan(""))})), "amp@0");
  EXPECT_EQ(field_of(model_of({mode(100, 1, -1)})), "amp@0");
  EXPECT_EQ(field_of(model_of({mode(100, 1, 1), mode(0, 1, 1)})), "freq_hz@1");
  EXPECT_EQ(field_of(model_of({mode(100, 1e-300, 1e200)})), "decay_per_s@0");  // power overflows
}

TEST(MaskingPruning, RejectsOptionsOutOfRange) {
  auto field_of = [](double a_v, double playback) {
    PruneOptions o;
    o.threshold_db = a_v;
    o.playback_db = playback;
    try {
      validate_prune_options(o);
    } catch (const PruneError& e) {
      EXPECT_EQ(e.mode(), PruneError::kNoMode);
      return e.field();
    }
    return std::string("ok");
  };
  EXPECT_EQ(field_of(-20, 0), "ok");
  EXPECT_EQ(field_of(60, 130), "ok");
  EXPECT_EQ(field_of(-20.001, 70), "threshold_db");
  EXPECT_EQ(field_of(60.5, 70), "threshold_db");
  EXPECT_EQ(field_of(std::nan(""), 70), "threshold_db");
  EXPECT_EQ(field_of(16, -1), "playback_db");
  EXPECT_EQ(field_of(16, 130.1), "playback_db");
}

// Random models as in the benchmark, plus the awkward cases: duplicated frequencies (equal Bark),
// silent modes, loud levels whose upper slope is 0 (L >= 110 dB), extreme a_v, and (amp_floor 1e-100)
// levels down to -2000 dB whose slopes reach 400 dB/Bark.
ModalModel random_model(std::size_t n, std::uint64_t seed, bool awkward, double amp_floor = 1e-4) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> logf(std::log(50.0), std::log(16000.0));
  std::uniform_real_distribution<double> decay(1.0, 100.0), loga(std::log(amp_floor), 0.0), u(0, 1);
  ModalModel m;
  for (std::size_t i = 0; i < n; ++i) {
    Mode md{std::exp(logf(rng)), decay(rng), std::exp(loga(rng)), 0.0};
    if (awkward && i > 0 && u(rng) < 0.2) md.freq_hz = m.modes[std::size_t(u(rng) * double(i))].freq_hz;
    if (awkward && u(rng) < 0.05) md.amp = 0.0;
    m.modes.push_back(md);
  }
  return m;
}

void expect_fast_equals_naive(const ModalModel& m, double a_v, double playback, MaskingCombine c,
                              double tolerance_db) {
  const std::vector<double> level = mode_levels_db(mode_powers(m), playback);
  std::vector<double> bark;
  for (const Mode& md : m.modes) bark.push_back(bark_zwicker_terhardt(md.freq_hz));
  const auto fast = masking_threshold_db(bark, level, a_v, c);
  const auto naive = masking_threshold_db_naive(bark, level, a_v, c);
  ASSERT_EQ(fast.size(), naive.size());
  for (std::size_t i = 0; i < fast.size(); ++i) {
    if (naive[i] == -kInf) {
      EXPECT_EQ(fast[i], -kInf) << "mode " << i;
      continue;
    }
    // Rounding errors scale with |T| (levels far below 0 dB come from tiny powers).
    EXPECT_NEAR(fast[i], naive[i], tolerance_db * std::max(1.0, std::abs(naive[i]) / 100.0))
        << "mode " << i << " of " << fast.size() << ", combine " << to_string(c);
  }
}

TEST(MaskingPruning, FastMaxEqualsNaiveOnRandomSets) {
  for (std::size_t n : {1u, 2u, 3u, 10u, 100u, 1000u, 3000u})
    for (std::uint64_t seed : {1u, 2u, 3u})
      for (bool awkward : {false, true})
        for (auto [a_v, playback] : {std::pair{16.0, 70.0}, {-20.0, 130.0}, {60.0, 0.0}, {5.0, 80.0}})
          expect_fast_equals_naive(random_model(n, seed, awkward), a_v, playback, MaskingCombine::max, 1e-9);
}

// Tolerance for sum: the bucketed Taylor sums are good to ~5e-12 relative in power (header).
TEST(MaskingPruning, FastSumEqualsNaiveOnRandomSets) {
  for (std::size_t n : {1u, 2u, 3u, 10u, 100u, 1000u})
    for (std::uint64_t seed : {1u, 2u, 3u})
      for (bool awkward : {false, true})
        for (auto [a_v, playback] : {std::pair{16.0, 70.0}, {-20.0, 130.0}, {60.0, 0.0}, {5.0, 80.0}})
          expect_fast_equals_naive(random_model(n, seed, awkward), a_v, playback, MaskingCombine::sum, 1e-9);
  expect_fast_equals_naive(random_model(3000, 4, true), 16.0, 70.0, MaskingCombine::sum, 1e-9);
  for (MaskingCombine c : {MaskingCombine::max, MaskingCombine::sum})
    expect_fast_equals_naive(random_model(1000, 5, true, 1e-100), 16.0, 70.0, c, 1e-9);
}

// The whole rule, fast path, against verdicts recomputed from the naive thresholds.
TEST(MaskingPruning, PrunedSetMatchesNaiveVerdicts) {
  for (MaskingCombine c : {MaskingCombine::max, MaskingCombine::sum}) {
    const ModalModel m = random_model(2000, 7, true);
    PruneOptions o;
    o.combine = c;
    const PruneResult r = prune_modes(m, o);
    const auto naive = masking_threshold_db_naive(r.bark, r.level_db, o.threshold_db, c);
    std::size_t audible = 0;
    for (std::size_t i = 0; i < m.modes.size(); ++i) {
      const double margin = r.level_db[i] - std::max(naive[i], r.quiet_db[i]);
      if (std::abs(margin) > 1e-9) {
        EXPECT_EQ(r.audible[i], margin >= 0) << i;
      }
      audible += r.audible[i];
    }
    EXPECT_EQ(r.kept.size(), audible);
    EXPECT_EQ(r.kept.size() + r.dropped.size(), m.modes.size());
    EXPECT_GT(audible, 10u);
    EXPECT_LT(audible, m.modes.size());
  }
}

TEST(MaskingPruning, ProgressiveModelTakesTheFirstKKept) {
  ModalModel m = model_of({mode(1100, 10, 1), mode(1000, 1, 0.5), mode(60, 0.5, 0.4)});
  m.hit_point_names = {"rim", "base"};
  m.hit_gains = {{1, 2, 3}, {4, 5, 6}};
  const PruneResult r = prune_modes(m, PruneOptions{});  // energy: 2, 1, 0
  const ModalModel two = progressive_model(m, r, 2);
  ASSERT_EQ(two.modes.size(), 2u);
  EXPECT_EQ(two.modes[0].freq_hz, 60.0);
  EXPECT_EQ(two.modes[1].freq_hz, 1000.0);
  EXPECT_EQ(two.hit_gains, (std::vector<std::vector<double>>{{3, 2}, {6, 5}}));
  EXPECT_EQ(progressive_model(m, r, 10).modes.size(), 3u);
}

TEST(MaskingPruning, NamesRoundTrip) {
  for (auto m : {PruneMethod::masking, PruneMethod::naive, PruneMethod::energy, PruneMethod::loudness})
    EXPECT_EQ(parse_prune_method(to_string(m)), m);
  for (auto o : {ModeOrder::naive, ModeOrder::energy, ModeOrder::loudness})
    EXPECT_EQ(parse_mode_order(to_string(o)), o);
  EXPECT_EQ(parse_masking_combine("sum"), MaskingCombine::sum);
  EXPECT_FALSE(parse_prune_method("Masking").has_value());
}

}  // namespace
}  // namespace ms
