// A candidate's render with the modes cut where their envelope falls under a floor, against the whole render.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "analysis/estimation/candidate_render.hpp"
#include "synthesis/material.hpp"
#include "synthesis/reference_objects.hpp"

namespace ms {
namespace {

ModalModel plastic_plate(double fs) {
  const ObjectModes om = free_circular_plate(0.10, 0.003, 0.33, {0.3}, 1e12, 60);
  const Material& m = *find_material("ren2013/plastic");
  return candidate_model({om.lambda0, om.gains[0], {}},
                         {m.rayleigh.alpha1, m.rayleigh.alpha2, m.specific_modulus_m2_s2, 0.01}, fs / 2);
}

TEST(CandidateRender, WithoutAFloorItIsTheWholeRender) {
  const double fs = 44100;
  const ModalModel model = plastic_plate(fs);
  Excitation strike;
  strike.shape = PulseShape::raised_cosine;
  strike.contact_s = 0.5e-3;
  EXPECT_EQ(render_candidate_above(model, strike, fs, 4410, 0.0), render_candidate(model, strike, fs, 4410));
}

TEST(CandidateRender, EachSampleStaysWithinTheFloorPerModeOfTheWholeRender) {
  const double fs = 44100;
  const ModalModel model = plastic_plate(fs);
  ASSERT_GE(model.modes.size(), 20u);
  for (const bool impulse : {true, false}) {
    Excitation strike;
    if (!impulse) strike.shape = PulseShape::hertz, strike.contact_s = 0.8e-3;
    const std::size_t frames = std::size_t(fs);
    const std::vector<float> whole = render_candidate(model, strike, fs, frames);
    float peak = 0;
    for (float v : whole) peak = std::max(peak, std::abs(v));
    const double floor_amp = 1e-4 * peak;
    const std::vector<float> cut = render_candidate_above(model, strike, fs, frames, floor_amp);
    ASSERT_EQ(cut.size(), frames);
    double worst = 0, differing = 0;
    for (std::size_t i = 0; i < frames; ++i) {
      worst = std::max(worst, double(std::abs(cut[i] - whole[i])));
      differing += cut[i] != whole[i];
    }
    EXPECT_LE(worst, double(model.modes.size()) * floor_amp + 1e-6 * peak) << impulse;
    // It did cut something: the plate's fast upper modes end long before the second.
    EXPECT_GT(differing, 0.0) << impulse;
  }
}

TEST(CandidateRender, TheContactAndTheFreeDecaysAreTheBanksToFloatRounding) {
  // A floor far below every mode: nothing is cut, and the head (the contact, summed here) and the
  // free decays (the bank from the contact's end state) agree with the bank's own render.
  const double fs = 44100;
  const ModalModel model = plastic_plate(fs);
  for (const PulseShape shape : {PulseShape::raised_cosine, PulseShape::hertz}) {
    Excitation strike;
    strike.shape = shape;
    strike.contact_s = 1.3e-3;
    strike.gain = 2.0;
    const std::vector<float> whole = render_candidate(model, strike, fs, 8820);
    float peak = 0;
    for (float v : whole) peak = std::max(peak, std::abs(v));
    const std::vector<float> cut = render_candidate_above(model, strike, fs, 8820, 1e-12 * peak);
    double worst = 0;
    for (std::size_t i = 0; i < whole.size(); ++i) worst = std::max(worst, double(std::abs(cut[i] - whole[i])));
    EXPECT_LE(worst, 1e-5 * peak) << int(shape);
  }
}

}  // namespace
}  // namespace ms
