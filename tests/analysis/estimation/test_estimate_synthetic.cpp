// The estimation's proof on synthetic recordings: the shipped bar and plate parameter sets rendered
// by the project (render_stimulus) with random materials inside the box of the library's Ren and
// Sterling materials, a random contact the estimator is not told, and white noise 40 dB below the
// peak; the estimate must land within the tolerances on at least 90 % of the cases.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

#include "analysis/estimation/estimate_material.hpp"
#include "analysis/extraction/feature_extraction.hpp"
#include "synthesis/material.hpp"
#include "synthesis/paramset.hpp"
#include "synthesis/stimulus.hpp"

namespace ms {
namespace {

constexpr const char* kBar = MODALSTUDY_SOURCE_DIR "/stimuli/bar/ren-wood.yaml";
constexpr const char* kPlate = MODALSTUDY_SOURCE_DIR "/stimuli/plate/ren-wood.yaml";

// Tolerances of the claim: relative errors.
constexpr double kTolAlpha = 0.10, kTolBeta = 0.10, kTolGamma = 0.02, kTolSigma = 0.10;

// The smallest box holding every Ren and Sterling material of the library (sigma: Ren's only, the
// Sterling materials do not publish one).
struct Box {
  double lo = HUGE_VAL, hi = 0.0;
  void add(double v) { lo = std::min(lo, v), hi = std::max(hi, v); }
};

struct LibraryMaterials {
  std::vector<const Material*> materials;
  Box alpha, beta, gamma, sigma;
  LibraryMaterials() {
    for (const Material& m : material_library()) {
      const bool ren = m.id.rfind("ren2013/", 0) == 0, sterling = m.id.rfind("sterling2019/", 0) == 0;
      if (!ren && !sterling) continue;
      materials.push_back(&m);
      alpha.add(m.rayleigh.alpha1);
      beta.add(m.rayleigh.alpha2);
      gamma.add(m.specific_modulus_m2_s2);
      if (ren) sigma.add(m.amp_scale);
    }
  }
};

struct SyntheticCase {
  std::uint64_t seed = 0;
  bool plate = false;
  std::string near;  // the library material it was drawn around
  Candidate truth;
  double contact_s = 0.0;
};

// A material near a random library one: alpha, beta and gamma each within a factor 2 of it
// (log-uniform), kept inside the library's box; sigma log-uniform over Ren's. Independent draws over
// the whole box would pair, e.g., an alpha of 0.04/s with a beta of 3e-6 s, a material whose alpha
// no sound reveals (beta lambda is 1000 times alpha at its lowest mode).
SyntheticCase draw_case(std::uint64_t seed, bool plate) {
  static const LibraryMaterials lib;
  std::mt19937_64 g(seed);
  auto near = [&](double v, const Box& b) {
    const double f = std::exp(std::uniform_real_distribution<double>(std::log(0.5), std::log(2.0))(g));
    return std::clamp(v * f, b.lo, b.hi);
  };
  SyntheticCase c;
  c.seed = seed;
  c.plate = plate;
  const Material& m = *lib.materials[std::uniform_int_distribution<std::size_t>(0, lib.materials.size() - 1)(g)];
  c.near = m.id;
  c.truth.alpha = near(m.rayleigh.alpha1, lib.alpha);
  c.truth.beta = near(m.rayleigh.alpha2, lib.beta);
  c.truth.gamma = near(m.specific_modulus_m2_s2, lib.gamma);
  c.truth.sigma = std::exp(std::uniform_real_distribution<double>(std::log(lib.sigma.lo), std::log(lib.sigma.hi))(g));
  c.contact_s = std::uniform_real_distribution<double>(0.3e-3, 1.0e-3)(g);
  return c;
}

std::string num(double v) {
  char s[40];
  std::snprintf(s, sizeof s, "%.17g", v);
  return s;
}

// The parameter set with the case's material and contact, unnormalised (sigma is an absolute scale),
// rendered as the project renders a stimulus, plus seeded white noise 40 dB under the peak.
std::vector<float> synthetic_recording(const SyntheticCase& c, double& sample_rate_hz) {
  const ParamSet set = load_paramset(
      c.plate ? kPlate : kBar,
      {"damping.law=rayleigh", "damping.alpha1=" + num(c.truth.alpha), "damping.alpha2=" + num(c.truth.beta),
       "specific_modulus_m2_s2=" + num(c.truth.gamma), "amp_scale=" + num(c.truth.sigma),
       "excitation.contact_s=" + num(c.contact_s), "level.normalize=none"});
  const RenderedStimulus r = render_stimulus(set);
  sample_rate_hz = r.audio.sample_rate_hz;
  std::vector<float> x = r.audio.samples;
  float peak = 0;
  for (float v : x) peak = std::max(peak, std::abs(v));
  std::mt19937_64 g(c.seed ^ 0x9e3779b97f4a7c15ULL);
  std::normal_distribution<double> noise(0.0, peak * std::pow(10.0, -40.0 / 20.0));
  for (float& v : x) v = float(v + noise(g));
  return x;
}

struct CaseResult {
  SyntheticCase c;
  Candidate estimate;
  double estimated_contact_s = 0.0;
  std::size_t modes = 0;
  double seconds = 0.0;
  double err_alpha = 0, err_beta = 0, err_gamma = 0, err_sigma = 0;
  bool pass = false;
  std::string error;  // why no estimate came back
};

double rel(double estimate, double truth) { return estimate / truth - 1.0; }

// Diagnosis (MODALSTUDY_ESTIMATE_VERBOSE set): the extracted modes with their weights and the truth's
// mode each lies nearest to, every start with its circle, eigenvalue, metric before and after, and
// the truth's own metric.
void print_starts(const SyntheticCase& c, const ExtractedFeatures& f, const MaterialEstimate& e,
                  const std::vector<float>& x, double fs, const ObjectEigen& object, const EstimateOptions& o) {
  const ModalModel truth = candidate_model(object, c.truth, 0.5 * fs);
  const std::size_t frames = std::min(x.size(), std::size_t(o.max_duration_s * fs));
  const PerceptualReference ref(std::vector<float>(x.begin(), x.begin() + std::ptrdiff_t(frames)), fs, f.modes,
                                o.perceptual);
  for (std::size_t i = 0; i < f.modes.size(); ++i) {
    const Mode& m = f.modes[i];
    std::size_t near = 0;
    for (std::size_t k = 0; k < truth.modes.size(); ++k)
      if (std::abs(truth.modes[k].freq_hz - m.freq_hz) < std::abs(truth.modes[near].freq_hz - m.freq_hz)) near = k;
    std::printf("   mode %2zu f %8.1f d %8.2f amp %9.3g w %9.3g | truth mode %3zu f %8.1f d %8.2f amp %9.3g\n", i,
                m.freq_hz, m.decay_per_s, m.amp, ref.features()[i].weight, near, truth.modes[near].freq_hz,
                truth.modes[near].decay_per_s, truth.modes[near].amp);
  }
  for (const StartResult& s : e.starts)
    std::printf("   start modes %zu,%zu eig %3zu a %9.4g b %9.3g g %9.4g s %9.3g -> a %+7.1f%% b %+7.1f%% g %+7.2f%% "
                "s %+7.1f%% tau %.3f ms hybrid %.5g (%zu evals)\n",
                s.start.mode_a, s.start.mode_b, s.start.eigenvalue, s.initial.alpha, s.initial.beta, s.initial.gamma,
                s.initial.sigma, 100 * rel(s.fitted.alpha, c.truth.alpha), 100 * rel(s.fitted.beta, c.truth.beta),
                100 * rel(s.fitted.gamma, c.truth.gamma), 100 * rel(s.fitted.sigma, c.truth.sigma), s.contact_s * 1e3,
                s.scores.hybrid, s.evaluations);
  std::vector<double> weights;
  for (const FeaturePoint& p : ref.features()) weights.push_back(p.weight);
  const std::vector<StartPoint> all =
      start_points(f.modes, weights, object.lambda0, object.gain, o.dominant_modes, o.start_eigenvalues);
  std::size_t near_gamma = 0;
  for (const StartPoint& s : all) near_gamma += std::abs(s.stiffness_ratio / c.truth.gamma - 1.0) < 0.05;
  const PerceptualScores t = score_candidate(x, fs, f.modes, object, object.strike, c.truth, c.contact_s, o);
  std::printf("   %zu start points, %zu with gamma within 5 %%; truth's metric %.5g = %.5g / %.4f (its contact), "
              "estimate's %.5g = %.5g / %.4f\n",
              all.size(), near_gamma, t.hybrid, t.psycho, -t.match.product, e.scores.hybrid, e.scores.psycho,
              -e.scores.match.product);
}

CaseResult run_case(const SyntheticCase& c) {
  static const ObjectEigen bar = object_eigen_from_paramset(kBar), plate = object_eigen_from_paramset(kPlate);
  const ObjectEigen& object = c.plate ? plate : bar;
  double fs = 0;
  const std::vector<float> x = synthetic_recording(c, fs);
  ExtractOptions extract;  // as modalstudy estimate extracts
  extract.skip_contact_s = 0.5e-3;
  extract.max_attack_skip_s = 20e-3;
  const ExtractedFeatures f = extract_features(x, fs, extract);
  CaseResult r;
  r.c = c;
  r.modes = f.modes.size();
  const auto t0 = std::chrono::steady_clock::now();
  try {
    EstimateOptions o;
    o.noise_sigma = f.noise_sigma;
    const MaterialEstimate e = estimate_material(x, fs, f.modes, object, object.strike, o);
    if (std::getenv("MODALSTUDY_ESTIMATE_VERBOSE")) print_starts(c, f, e, x, fs, object, o);
    r.estimate = e.material;
    r.estimated_contact_s = e.contact_s;
  } catch (const std::invalid_argument& e) {
    r.estimate = {NAN, NAN, NAN, NAN};
    r.error = e.what();
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.err_alpha = rel(r.estimate.alpha, c.truth.alpha);
  r.err_beta = rel(r.estimate.beta, c.truth.beta);
  r.err_gamma = rel(r.estimate.gamma, c.truth.gamma);
  r.err_sigma = rel(r.estimate.sigma, c.truth.sigma);
  r.pass = std::abs(r.err_alpha) <= kTolAlpha && std::abs(r.err_beta) <= kTolBeta &&
           std::abs(r.err_gamma) <= kTolGamma && std::abs(r.err_sigma) <= kTolSigma;
  return r;
}

void print_row(const CaseResult& r) {
  std::printf("%6llu %-5s %-24s %9.4g %9.3g %9.4g %9.3g %6.3f %6.3f | %+7.1f%% %+7.1f%% %+7.2f%% %+7.1f%% %3zu %5.1fs %s\n",
              static_cast<unsigned long long>(r.c.seed), r.c.plate ? "plate" : "bar", r.c.near.c_str(), r.c.truth.alpha, r.c.truth.beta,
              r.c.truth.gamma, r.c.truth.sigma, r.c.contact_s * 1e3, r.estimated_contact_s * 1e3, 100 * r.err_alpha,
              100 * r.err_beta, 100 * r.err_gamma, 100 * r.err_sigma, r.modes, r.seconds, r.pass ? "ok" : "FAIL");
  if (!r.error.empty()) std::printf("       %s\n", r.error.c_str());
}

// The seeds: 1000-1049 were used to tune the estimator; the proof draws 2000-2049 (bar on even,
// plate on odd seeds), disjoint from them.
constexpr std::uint64_t kFirstSeed = 2000;
constexpr std::size_t kCases = 50;

// MODALSTUDY_ESTIMATE_SEEDS=FIRST-LAST runs those seeds instead (tuning runs on seeds disjoint from the proof's).
std::pair<std::uint64_t, std::size_t> seed_range() {
  if (const char* s = std::getenv("MODALSTUDY_ESTIMATE_SEEDS")) {
    unsigned long long first = 0, last = 0;
    if (std::sscanf(s, "%llu-%llu", &first, &last) == 2 && last >= first) return {first, std::size_t(last - first + 1)};
  }
  return {kFirstSeed, kCases};
}

// About 3 minutes (its own CTest entry). Measured: 46 of 50 pass; the four misses are three bars
// with 2 to 5 heard modes (alpha -14 %, sigma -14 % with the contact read 0.64 ms for 0.78, beta
// +11 %) and one metal plate (beta +10.5 %).
TEST(EstimateSynthetic, RecoversRandomMaterialsThroughNoiseAndAnUnknownContact) {
  std::vector<CaseResult> results;
  std::size_t passed = 0;
  std::printf("  seed obj   near                         alpha      beta     gamma     sigma tau_ms est_ms |  alpha    beta    gamma    sigma  modes  time\n");
  const auto [first_seed, cases] = seed_range();
  for (std::size_t i = 0; i < cases; ++i) {
    const std::uint64_t seed = first_seed + i;
    results.push_back(run_case(draw_case(seed, seed % 2 == 1)));
    print_row(results.back());
    std::fflush(stdout);
    passed += results.back().pass;
  }
  std::printf("failures:\n");
  for (const CaseResult& r : results)
    if (!r.pass) print_row(r);
  std::printf("passed %zu of %zu\n", passed, results.size());
  EXPECT_GE(double(passed), 0.9 * double(results.size()));
}

// Geometry invariance (Ren 2014, Ch. 2): one material recorded on the bar and on the plate (each
// with its own contact and noise) gives one estimate, within the tolerances above.
struct RenMaterialSeed {
  const char* material;
  std::uint64_t seed;  // of the noise
};
class EstimateGeometryInvariance : public ::testing::TestWithParam<RenMaterialSeed> {};

// About 15 s per material. Porcelain's alpha (0.037 1/s, small beside beta lambda at every heard mode)
// comes out 15 % and 20 % low on bar and plate, but the two agree within the tolerance.
TEST_P(EstimateGeometryInvariance, BarAndPlateOfOneRenMaterialGiveTheSameEstimate) {
  const Material& m = *find_material(std::string("ren2013/") + GetParam().material);
  SyntheticCase c;
  c.near = m.id;
  c.truth = {m.rayleigh.alpha1, m.rayleigh.alpha2, m.specific_modulus_m2_s2, m.amp_scale};
  c.seed = GetParam().seed;
  c.contact_s = 0.4e-3;
  const CaseResult bar = run_case(c);
  c.plate = true;
  c.contact_s = 0.8e-3;
  const CaseResult plate = run_case(c);
  print_row(bar);
  print_row(plate);
  EXPECT_NEAR(bar.estimate.alpha / plate.estimate.alpha, 1.0, kTolAlpha);
  EXPECT_NEAR(bar.estimate.beta / plate.estimate.beta, 1.0, kTolBeta);
  EXPECT_NEAR(bar.estimate.gamma / plate.estimate.gamma, 1.0, kTolGamma);
  EXPECT_NEAR(bar.estimate.sigma / plate.estimate.sigma, 1.0, kTolSigma);
}

INSTANTIATE_TEST_SUITE_P(Ren, EstimateGeometryInvariance,
                         ::testing::Values(RenMaterialSeed{"wood", 3001}, RenMaterialSeed{"plastic", 3002},
                                           RenMaterialSeed{"metal", 3003}, RenMaterialSeed{"glass", 3004},
                                           RenMaterialSeed{"porcelain", 3005}),
                         [](const ::testing::TestParamInfo<RenMaterialSeed>& info) {
                           return std::string(info.param.material);
                         });

}  // namespace
}  // namespace ms
