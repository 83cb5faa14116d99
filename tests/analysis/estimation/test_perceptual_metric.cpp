// The perceptual metric of Ren et al. (analysis/estimation/): ISO 226:2003 contours against the
// standard's own numbers, phon -> sone, the Bark power image against SciPy
// (tests/data/perceptual_metric/make_golden.py), the loudness image, k(D), the match ratios on
// hand-made sets, the loudness weights of modes, Pi_psycho and Pi_hybrid.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "analysis/estimation/feature_match.hpp"
#include "analysis/estimation/iso226_loudness.hpp"
#include "analysis/estimation/loudness_image.hpp"
#include "analysis/estimation/perceptual_metric.hpp"
#include "synthesis/tidy_csv.hpp"
#include "synthesis/bark.hpp"
#include "synthesis/reference_renderer.hpp"

using namespace ms;

namespace {

const std::string kDir = std::string(MODALSTUDY_TEST_DATA) + "/perceptual_metric/";
constexpr double kFs = 44100.0;

std::vector<float> render(const std::vector<Mode>& modes, double seconds, double gain = 1.0) {
  ModalModel m;
  m.modes = modes;
  const std::vector<double> y = render_reference(m, {}, kFs, std::size_t(seconds * kFs));
  std::vector<float> out(y.size());
  for (std::size_t i = 0; i < y.size(); ++i) out[i] = float(gain * y[i]);
  return out;
}

// The samples make_golden.py analyses.
std::vector<float> golden_signal() {
  const std::size_t n = std::size_t(0.3 * kFs);
  std::vector<float> x(n);
  const double two_pi = 2.0 * std::acos(-1.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = double(i) / kFs;
    x[i] = float(0.5 * std::exp(-3.0 * t) * std::sin(two_pi * 440.0 * t) +
                 0.2 * std::exp(-30.0 * t) * std::sin(two_pi * 2500.0 * t + 0.3) +
                 0.05 * std::exp(-100.0 * t) * std::sin(two_pi * 7100.0 * t));
  }
  return x;
}

}  // namespace

// --- ISO 226:2003 -------------------------------------------------------------------------------

TEST(Iso226, TableRowsAsPrintedInTheStandard) {
  const auto& t = iso226_table();
  ASSERT_EQ(t.size(), 29u);
  for (std::size_t i = 1; i < t.size(); ++i) EXPECT_LT(t[i - 1].freq_hz, t[i].freq_hz);
  // ISO 226:2003 Table 1: first, 1 kHz and last rows.
  EXPECT_EQ(t.front().freq_hz, 20.0);
  EXPECT_EQ(t.front().alpha_f, 0.532);
  EXPECT_EQ(t.front().lu_db, -31.6);
  EXPECT_EQ(t.front().tf_db, 78.5);
  EXPECT_EQ(t[17].freq_hz, 1000.0);
  EXPECT_EQ(t[17].alpha_f, 0.250);
  EXPECT_EQ(t[17].lu_db, 0.0);
  EXPECT_EQ(t[17].tf_db, 2.4);
  EXPECT_EQ(t.back().freq_hz, 12500.0);
  EXPECT_EQ(t.back().alpha_f, 0.301);
  EXPECT_EQ(t.back().tf_db, 12.3);
}

TEST(Iso226, OneKilohertzRowGivesSplEqualToPhon) {
  // The phon is defined at 1 kHz: the formula's 1 kHz row returns L_p = L_N to about 0.01 dB.
  const Iso226Row r = iso226_parameters(1000.0);
  for (double phon = 0.0; phon <= 100.0; phon += 10.0) EXPECT_NEAR(iso226_spl_db(r, phon), phon, 0.02) << phon;
}

TEST(Iso226, FortyPhonContourMatchesTheStandard) {
  // ISO 226:2003, the 40-phon normal equal-loudness-level contour (dB SPL, to 0.1 dB).
  const std::vector<std::pair<double, double>> published = {
      {20.0, 99.9},  {63.0, 73.1},   {100.0, 64.4},  {250.0, 50.4},  {500.0, 43.1},
      {1000.0, 40.0}, {2000.0, 39.2}, {3150.0, 35.6}, {8000.0, 51.8}, {12500.0, 51.5}};
  for (const auto& [f, spl] : published)
    EXPECT_NEAR(iso226_spl_db(iso226_parameters(f), 40.0), spl, 0.051) << f << " Hz";
}

TEST(Iso226, LoudnessLevelInvertsTheContour) {
  // Eq. (2) is the standard's own inverse of Eq. (1), with separately rounded constants (4.47e-3 *
  // 1.15 against 0.005135, 4.47e-3 against 10^(-94/40)): they agree to 0.06 phon, worst at 20 Hz.
  for (const Iso226Row& r : iso226_table())
    for (double phon = 10.0; phon <= 90.0; phon += 10.0)
      EXPECT_NEAR(iso226_loudness_phon(r, iso226_spl_db(r, phon)), phon, 0.06) << r.freq_hz << " Hz";
  EXPECT_NEAR(iso226_loudness_phon(iso226_parameters(1000.0), 60.0), 60.0, 0.03);
  // At the threshold of hearing T_f, B_f is 0.005135: 40 lg(0.005135) + 94 = 2.42 phon.
  const Iso226Row r = iso226_parameters(1000.0);
  EXPECT_NEAR(iso226_loudness_phon(r, r.tf_db), 40.0 * std::log10(0.005135) + 94.0, 1e-12);
  // Far below the threshold: a negative loudness level, i.e. 0 sone.
  EXPECT_LT(iso226_loudness_phon(r, -80.0), 0.0);
  EXPECT_EQ(sone_from_phon(iso226_loudness_phon(r, -80.0)), 0.0);
  // No row's T_f term exceeds 0.005135, so B_f stays positive and the level stays finite everywhere.
  for (const Iso226Row& row : iso226_table()) EXPECT_TRUE(std::isfinite(iso226_loudness_phon(row, -200.0)));
}

TEST(Iso226, ParametersBetweenRowsAndOutside) {
  const auto& t = iso226_table();
  const Iso226Row at = iso226_parameters(2500.0);
  EXPECT_EQ(at.tf_db, t[21].tf_db);
  // Geometric mean of 1000 and 1250 Hz: half way in log frequency.
  const Iso226Row mid = iso226_parameters(std::sqrt(1000.0 * 1250.0));
  EXPECT_NEAR(mid.alpha_f, 0.5 * (0.250 + 0.246), 1e-12);
  EXPECT_NEAR(mid.lu_db, 0.5 * (0.0 - 2.7), 1e-12);
  EXPECT_NEAR(mid.tf_db, 0.5 * (2.4 + 3.5), 1e-12);
  EXPECT_EQ(iso226_parameters(5.0).tf_db, 78.5);
  EXPECT_EQ(iso226_parameters(18000.0).tf_db, 12.3);
}

TEST(Iso226, SoneFromPhon) {
  EXPECT_DOUBLE_EQ(sone_from_phon(40.0), 1.0);
  EXPECT_DOUBLE_EQ(sone_from_phon(50.0), 2.0);
  EXPECT_DOUBLE_EQ(sone_from_phon(80.0), 16.0);
  EXPECT_DOUBLE_EQ(sone_from_phon(30.0), std::pow(0.75, 2.642));  // below 40 phon: (L/40)^2.642
  EXPECT_NEAR(sone_from_phon(40.0 - 1e-9), 1.0, 1e-8);            // continuous at 40 phon
  EXPECT_EQ(sone_from_phon(0.0), 0.0);
  EXPECT_EQ(sone_from_phon(-5.0), 0.0);
  EXPECT_EQ(sone_from_phon(-std::numeric_limits<double>::infinity()), 0.0);
}

TEST(Iso226, ToneLoudnessIsTheChainFolded) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> log_power(-12.0, 0.0), freq(30.0, 16000.0), cal(60.0, 110.0);
  for (int i = 0; i < 200; ++i) {
    const Iso226Row r = iso226_parameters(freq(rng));
    const double offset = cal(rng), p = std::pow(10.0, log_power(rng));
    const ToneLoudness tone(r, offset);
    const double phon = iso226_loudness_phon(r, offset + 10.0 * std::log10(p));
    if (std::isfinite(phon)) {
      EXPECT_NEAR(tone.phon(p), phon, 1e-9);
    }
    EXPECT_NEAR(tone.sone(p), sone_from_phon(phon), 1e-9 * (1.0 + sone_from_phon(phon)));
  }
  EXPECT_EQ(ToneLoudness(iso226_parameters(1000.0), 90.0).sone(0.0), 0.0);
}

// --- Images --------------------------------------------------------------------------------------

TEST(LoudnessImage, BarkPowerMatchesScipy) {
  const LoudnessImager imager(kFs);
  ASSERT_EQ(imager.window(), 1024u);
  const BarkImage p = imager.power(golden_signal());
  const BarkImage s = imager.loudness(p, db_spl_at_unit_power_for_full_scale(90.0));
  const TidyCsv g = TidyCsv::read(kDir + "bark_power_image.csv");
  ASSERT_EQ(g.rows(), p.frames * p.bands);
  double peak = 0.0;
  for (double v : p.cells) peak = std::max(peak, v);
  for (std::size_t r = 0; r < g.rows(); ++r) {
    const auto m = std::size_t(g.number(r, g.column("frame"))), b = std::size_t(g.number(r, g.column("band")));
    const double want = g.number(r, g.column("mean_square")), sone = g.number(r, g.column("sone"));
    EXPECT_NEAR(p.at(m, b), want, 1e-9 * want + 1e-12 * peak) << m << "," << b;
    EXPECT_NEAR(s.at(m, b), sone, 1e-6 * sone + 1e-9) << m << "," << b;
  }
}

TEST(LoudnessImage, SineMeanSquareAndOneSone) {
  // A steady 1 kHz sine of amplitude A: its bins sum to A^2/2 (up to the far leakage of the Hann
  // window); played with a 1 kHz, 40 dB SPL cell it is about 1 sone (the band centre is 965 Hz).
  const double a = 0.3;
  std::vector<float> x(std::size_t(0.5 * kFs));
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = float(a * std::sin(2.0 * std::acos(-1.0) * 1000.0 * double(i) / kFs));
  const LoudnessImager imager(kFs);
  const BarkImage p = imager.power(x);
  const std::size_t band = imager.band_of_hz(1000.0);
  EXPECT_EQ(band, 7u);  // 6 asinh(1000/600) = 7.70 Bark
  double total = 0.0;
  for (std::size_t b = 0; b < p.bands; ++b) total += p.at(3, b);
  EXPECT_NEAR(total, a * a / 2.0, 1e-4 * a * a);
  EXPECT_GT(p.at(3, band), 0.99 * total);
  const BarkImage s = imager.loudness(p, db_spl_at_unit_power_for_peak(p, 40.0));
  const double expected = sone_from_phon(iso226_loudness_phon(iso226_parameters(imager.band_centre_hz(band)), 40.0));
  EXPECT_NEAR(s.at(3, band), expected, 1e-6);  // frame 3 is within float rounding of the loudest one
  EXPECT_NEAR(s.at(3, band), 1.0, 0.06);
}

TEST(LoudnessImage, FramesAndEmptyInput) {
  const LoudnessImager imager(kFs);
  EXPECT_EQ(imager.power({}).frames, 0u);
  EXPECT_EQ(imager.power(std::vector<float>(100, 0.1f)).frames, 1u);  // one zero-padded frame
  EXPECT_EQ(imager.power(std::vector<float>(1024 + 3 * 512, 0.1f)).frames, 4u);
  EXPECT_EQ(imager.bands(), 26u);  // 6 asinh(22050/600) = 25.8 Bark
  EXPECT_THROW(LoudnessImager(0.0), std::invalid_argument);
}

// --- Pi_psycho -----------------------------------------------------------------------------------

TEST(PsychoMetric, ZeroForIdenticalAndGrowsWithLevelDifference) {
  const std::vector<Mode> modes = {{523.0, 3.0, 0.4, 0.0}, {1870.0, 25.0, 0.2, 0.0}, {4100.0, 60.0, 0.1, 0.0}};
  const std::vector<float> x = render(modes, 1.0);
  const PerceptualReference ref(x, kFs, modes);
  EXPECT_EQ(ref.psycho(x), 0.0);
  double previous = 0.0;
  for (double db : {1.0, 3.0, 6.0, 12.0}) {
    const double louder = ref.psycho(render(modes, 1.0, std::pow(10.0, db / 20.0)));
    const double quieter = ref.psycho(render(modes, 1.0, std::pow(10.0, -db / 20.0)));
    EXPECT_GT(louder, previous) << db;
    EXPECT_GT(quieter, 0.0) << db;
    previous = louder;
  }
}

TEST(PsychoMetric, MissingFramesAreSilenceAndGridsMustAgree) {
  BarkImage a, b;
  a.frames = 2;
  b.frames = 1;
  a.bands = b.bands = 2;
  a.cells = {1.0, 2.0, 3.0, 4.0};
  b.cells = {1.0, 1.0};
  EXPECT_DOUBLE_EQ(psycho_distance(a, b), 1.0 + 9.0 + 16.0);
  EXPECT_DOUBLE_EQ(psycho_distance(b, a), 26.0);
  b.bands = 1;
  b.cells = {1.0};
  EXPECT_THROW(psycho_distance(a, b), std::invalid_argument);
}

// --- Feature match -------------------------------------------------------------------------------

TEST(FeatureMatch, PointScoreBranches) {
  EXPECT_DOUBLE_EQ(point_match_score(0.0), 1.0);
  EXPECT_DOUBLE_EQ(point_match_score(0.5), 0.75);
  EXPECT_DOUBLE_EQ(point_match_score(1.0), 0.5);  // both branches give 0.5 at D = 1
  EXPECT_DOUBLE_EQ(point_match_score(1.0 + 1e-12), 0.5 / (1.0 + 1e-12));
  EXPECT_DOUBLE_EQ(point_match_score(2.0), 0.25);
  EXPECT_DOUBLE_EQ(point_match_score(5.0), 0.1);
  EXPECT_EQ(point_match_score(5.0 + 1e-9), 0.0);
  EXPECT_EQ(point_match_score(std::numeric_limits<double>::infinity()), 0.0);
}

TEST(FeatureMatch, DistanceInBarkAndDuration) {
  const FeaturePoint a{1000.0, 20.0, 1.0};
  // Same frequency, d 20 -> 25: 100/20 - 100/25 = 1.
  EXPECT_DOUBLE_EQ(feature_distance(a, {1000.0, 25.0, 1.0}), 1.0);
  // Same decay, 0.1 Bark higher: 5 * 0.1 = 0.5.
  const double f = 600.0 * std::sinh((bark_wang_sekey_gersho(1000.0) + 0.1) / 6.0);
  EXPECT_NEAR(feature_distance(a, {f, 20.0, 1.0}), 0.5, 1e-12);
  // Both: 3-4-5 triangle (0.6 Bark, 100/20 - 100/(100/9)).
  const double f3 = 600.0 * std::sinh((bark_wang_sekey_gersho(1000.0) + 0.6) / 6.0);
  EXPECT_NEAR(feature_distance(a, {f3, 100.0 / 9.0, 1.0}), 5.0, 1e-12);
  EXPECT_EQ(feature_distance(a, {1000.0, 0.0, 1.0}), std::numeric_limits<double>::infinity());
  FeatureMatchConstants c;
  c.c_d = 200.0;
  EXPECT_DOUBLE_EQ(feature_distance(a, {1000.0, 25.0, 1.0}, c), 2.0);
}

TEST(FeatureMatch, MatchRatiosOnHandMadeSets) {
  auto bark_shift = [](double f, double dz) { return 600.0 * std::sinh((bark_wang_sekey_gersho(f) + dz) / 6.0); };
  // Reference: A (1 kHz, d 20, weight 3), B (5 kHz, d 50, weight 1).
  const std::vector<FeaturePoint> ref = {{1000.0, 20.0, 3.0}, {5000.0, 50.0, 1.0}};
  // Estimate: A1 0.1 Bark above A (D = 0.5, k = 0.75), A2 on A's frequency at d 100/9 (D = 4, k =
  // 0.125), C far from both (10 kHz); unit weights.
  const std::vector<FeaturePoint> est = {{bark_shift(1000.0, 0.1), 20.0, 1.0}, {1000.0, 100.0 / 9.0, 1.0},
                                         {10000.0, 80.0, 1.0}};
  // Eq. 24: A's positive scores 0.75 and 0.125 average to 0.4375; B has none.
  EXPECT_NEAR(point_to_set_match(ref[0], est), (0.75 + 0.125) / 2.0, 1e-12);
  EXPECT_EQ(point_to_set_match(ref[1], est), 0.0);
  // Eq. 23: (3 * 0.4375 + 1 * 0) / 4.
  const MatchRatios r = match_ratio_product(ref, est);
  EXPECT_NEAR(r.reference, 3.0 * 0.4375 / 4.0, 1e-12);
  // Eq. 25: A1 -> 0.75, A2 -> 0.125, C -> 0, unit weights.
  EXPECT_NEAR(r.estimate, (0.75 + 0.125 + 0.0) / 3.0, 1e-12);
  EXPECT_NEAR(r.product, -r.reference * r.estimate, 1e-15);
  // Points of zero weight (inaudible) do not count; an empty or silent set matches nothing.
  std::vector<FeaturePoint> est_quiet_c = est;
  est_quiet_c[2].weight = 0.0;
  EXPECT_NEAR(set_match_ratio(est_quiet_c, ref), (0.75 + 0.125) / 2.0, 1e-12);
  EXPECT_EQ(set_match_ratio({}, ref), 0.0);
  EXPECT_EQ(match_ratio_product(ref, {}).product, 0.0);
  // A set against itself, points far apart: every ratio 1.
  EXPECT_DOUBLE_EQ(match_ratio_product(ref, ref).product, -1.0);
}

TEST(FeatureMatch, SetRatiosAreEq23OverPointToSetMatchesOnCrowdedSets) {
  // Points close enough that most pairs score (within 1 Bark and 1-10 ms of duration), some without a
  // positive decay, some without weight: the set ratios are Eq. 23 summed from point_to_set_match.
  std::mt19937_64 g(17);
  std::uniform_real_distribution<double> bark(7.0, 8.0), decay(-2.0, 40.0), weight(-0.5, 2.0);
  auto points = [&](std::size_t n) {
    std::vector<FeaturePoint> out(n);
    for (FeaturePoint& p : out) p = {600.0 * std::sinh(bark(g) / 6.0), decay(g), std::max(weight(g), 0.0)};
    return out;
  };
  const std::vector<FeaturePoint> ref = points(40), est = points(300);
  auto eq23 = [](const std::vector<FeaturePoint>& a, const std::vector<FeaturePoint>& b) {
    double num = 0.0, den = 0.0;
    for (const FeaturePoint& p : a)
      if (p.weight > 0.0) num += p.weight * point_to_set_match(p, b), den += p.weight;
    return num / den;
  };
  const MatchRatios r = match_ratio_product(ref, est);
  EXPECT_GT(r.reference, 0.1);
  EXPECT_DOUBLE_EQ(r.reference, eq23(ref, est));
  EXPECT_DOUBLE_EQ(r.estimate, eq23(est, ref));
  EXPECT_DOUBLE_EQ(set_match_ratio(est, ref), eq23(est, ref));
}

// --- Loudness weights and Pi_hybrid ----------------------------------------------------------------

TEST(HybridMetric, ModeWeightIsItsLoudnessImageSum) {
  // One mode in the middle of Bark band 9 (9.5 Bark): its image's loudness sum matches the closed
  // form weight (leakage into the neighbour bands is small there).
  const double f = 600.0 * std::sinh(9.5 / 6.0);
  const std::vector<Mode> mode = {{f, 8.0, 0.5, 0.0}};
  const std::vector<float> x = render(mode, 1.5);
  const LoudnessImager imager(kFs);
  const BarkImage p = imager.power(x);
  const double cal = db_spl_at_unit_power_for_peak(p, 70.0);
  const BarkImage s = imager.loudness(p, cal);
  double image_sum = 0.0;
  for (std::size_t m = 0; m < s.frames; ++m) image_sum += s.at(m, 9);
  image_sum *= s.hop_s;
  const std::vector<FeaturePoint> w = loudness_weighted_features(mode, imager, cal, s.frames);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NEAR(w[0].weight, image_sum, 0.03 * image_sum);
  // Louder modes weigh more; one above Nyquist or without a decay weighs nothing.
  const auto two = loudness_weighted_features({{f, 8.0, 0.5, 0.0}, {f, 8.0, 0.05, 0.0}, {30000.0, 8.0, 1.0, 0.0},
                                               {f, 0.0, 1.0, 0.0}},
                                              imager, cal, s.frames);
  EXPECT_GT(two[0].weight, two[1].weight);
  EXPECT_GT(two[1].weight, 0.0);
  EXPECT_EQ(two[2].weight, 0.0);
  EXPECT_EQ(two[3].weight, 0.0);
  // Far under the threshold of hearing: weight 0.
  EXPECT_EQ(loudness_weighted_features({{f, 8.0, 1e-7, 0.0}}, imager, cal, s.frames)[0].weight, 0.0);
}

TEST(HybridMetric, IdenticalSoundsScoreZeroAndMismatchScoresHigher) {
  const std::vector<Mode> modes = {{523.0, 3.0, 0.4, 0.0}, {1870.0, 25.0, 0.2, 0.0}, {4100.0, 60.0, 0.1, 0.0}};
  const std::vector<float> x = render(modes, 1.0);
  const PerceptualReference ref(x, kFs, modes);
  const PerceptualScores same = ref.compare(x, modes);
  EXPECT_EQ(same.psycho, 0.0);
  EXPECT_DOUBLE_EQ(same.match.product, -1.0);
  EXPECT_EQ(same.hybrid, 0.0);
  // Shift every mode by 3 %: the image and the features both move away.
  std::vector<Mode> shifted = modes;
  for (Mode& m : shifted) m.freq_hz *= 1.03;
  const PerceptualScores off = ref.compare(render(shifted, 1.0), shifted);
  EXPECT_GT(off.psycho, 0.0);
  EXPECT_GT(off.match.product, -1.0);
  EXPECT_LT(off.match.product, 0.0);
  EXPECT_DOUBLE_EQ(off.hybrid, off.psycho / -off.match.product);
  // Nothing matches: Pi_hybrid is infinite.
  EXPECT_EQ(hybrid_metric(1.0, MatchRatios{}), std::numeric_limits<double>::infinity());
  EXPECT_EQ(hybrid_metric(2.0, MatchRatios{0.5, 0.5, -0.25}), 8.0);
}

TEST(HybridMetric, NoiseByItsExpectedPowerIsTheRecordingsNoiseOnAverage) {
  // A recording of white noise alone: silence with the noise's expected power added lies closer to
  // it than another draw of the same noise does, and far closer than silence.
  const double sigma = 0.01;
  std::mt19937_64 g(7);
  std::normal_distribution<double> n(0.0, sigma);
  std::vector<float> a(static_cast<std::size_t>(kFs)), b(a.size());
  for (float& v : a) v = float(n(g));
  for (float& v : b) v = float(n(g));
  const PerceptualReference ref(a, kFs, {});
  const std::vector<float> silence(a.size(), 0.0f);
  const double expected = ref.compare(silence, {}, sigma).psycho, draw = ref.compare(b, {}).psycho,
               silent = ref.compare(silence, {}).psycho;
  EXPECT_LT(expected, draw);
  EXPECT_LT(expected, 0.05 * silent);
  // Without noise it is the plain comparison.
  EXPECT_EQ(ref.compare(b, {}, 0.0).psycho, ref.compare(b, {}).psycho);
}
