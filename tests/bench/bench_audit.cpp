// Audit speed: 10 strikes x 2 s (the bar: <= 10 s), hidden support damping + noise floor, a
// room (reverberation as a convolution), and the parts: feature extraction of all strikes and the
// repeatability floor vs the audit proper. A reference variant runs the cross-validation naively (every
// fold re-extracts the training strikes' features from audio); the room's fit scores a candidate room in
// closed form, against convolving each strike's rendering with a drawn impulse response.
#include <benchmark/benchmark.h>

#include <array>
#include <string>
#include <vector>

#include "analysis/audit/audit.hpp"
#include "analysis/audit/baseline_fit.hpp"
#include "analysis/audit/gap_target.hpp"
#include "analysis/audit/hidden_effect_generator.hpp"
#include "analysis/audit/repeatability_floor.hpp"
#include "analysis/audit/room_power.hpp"
#include "synthesis/resonator_bank.hpp"
#include "synthesis/room_response.hpp"

namespace {

ms::audit::HiddenCase ten_strikes(const std::vector<std::string>& effects = {"support_damping", "noise_floor"},
                                   double strength = 0.5) {
  ms::audit::GeneratorOptions g;
  g.strikes = 10;
  g.duration_s = 2.0;
  return ms::audit::generate_hidden_case(4242, effects, std::vector<double>(effects.size(), strength), g);
}

// The whole audit (extraction included) of the case's strikes, once per iteration.
void audit_each_iteration(benchmark::State& state, const ms::audit::HiddenCase& hc) {
  for (auto _ : state) {
    const auto data = ms::audit::make_audit_data(hc.recordings);
    const auto r = ms::audit::run_audit(data);
    benchmark::DoNotOptimize(r.gap_after_db);
  }
}

void BM_AuditTenStrikes(benchmark::State& state) {
  audit_each_iteration(state, ten_strikes());
}
BENCHMARK(BM_AuditTenStrikes)->Unit(benchmark::kMillisecond)->Iterations(3);

// The slowest kind of recording: a room tail (the extraction weighs candidates against it) and an
// attack burst (the extraction fits each strike twice, the second time from after the burst).
void BM_AuditTenStrikesReverbAndBurst(benchmark::State& state) {
  audit_each_iteration(state, ten_strikes({"reverberation", "residual_transient"}));
}
BENCHMARK(BM_AuditTenStrikesReverbAndBurst)->Unit(benchmark::kMillisecond)->Iterations(3);

// A room (RT60 0.3-1 s over the octaves, DRR +3 dB): the extraction weighs candidates against its
// coloured tail, and the reverberation extension fits a room in every fold.
void BM_AuditTenStrikesRoom(benchmark::State& state) {
  audit_each_iteration(state, ten_strikes({"reverberation"}));
}
BENCHMARK(BM_AuditTenStrikesRoom)->Unit(benchmark::kMillisecond)->Iterations(3);

// A strong room (strength 0.9): where the coarse grid's room is weak, the extension also starts from a
// strong guess and scores four candidate rooms with each mode's answer read in them.
void BM_AuditTenStrikesStrongRoom(benchmark::State& state) {
  audit_each_iteration(state, ten_strikes({"reverberation"}, 0.9));
}
BENCHMARK(BM_AuditTenStrikesStrongRoom)->Unit(benchmark::kMillisecond)->Iterations(3);

// One candidate room scored on the 10 strikes, as the room's fit does a few hundred times: the
// expected reverberant power in closed form (room_power.hpp) added to the renderings, and the gap.
struct RoomScoring {
  ms::audit::AuditData data = ms::audit::make_audit_data(ten_strikes({"reverberation"}).recordings);
  ms::audit::AuditModel model = ms::audit::fit_baseline(data, ms::audit::all_strikes(data));
  ms::Room room{.rt60_s = {0.9, 0.8, 0.7, 0.6, 0.5, 0.45, 0.4}, .drr_db = 3.0, .seed = 1, .enabled = true};
};

void BM_RoomCandidateClosedForm(benchmark::State& state) {
  const RoomScoring r;
  const double fs = r.data.measured.sample_rate_hz;
  const ms::audit::GapTarget target(r.data, ms::audit::all_strikes(r.data));
  const ms::audit::RoomRates rates = ms::audit::room_rates(r.room, fs);
  std::vector<ms::audit::Spectra> base;
  std::vector<std::array<ms::audit::RoomFootprint, ms::audit::kResolutions>> footprints;
  std::array<ms::audit::RoomGrid, ms::audit::kResolutions> grids;
  for (std::size_t k = 0; k < ms::audit::kResolutions; ++k) grids[k] = ms::audit::room_grid(r.data.measured.grids[k]);
  ms::audit::AuditModel in_room = r.model;
  in_room.room = r.room;
  for (std::size_t s = 0; s < r.data.strike_count(); ++s) {
    base.push_back(ms::audit::predict_spectra(in_room, r.data, s, nullptr, false));
    const ms::ModalModel dry = ms::audit::dry_strike_model(in_room, s, fs);
    footprints.emplace_back();
    for (std::size_t k = 0; k < ms::audit::kResolutions; ++k)
      footprints.back()[k] = ms::audit::room_footprint(r.data.measured.grids[k], grids[k], dry, &rates);
  }
  ms::audit::Spectra scratch;
  for (auto _ : state) {
    double gap = 0.0;
    for (std::size_t s = 0; s < base.size(); ++s) {
      scratch = base[s];
      for (std::size_t k = 0; k < ms::audit::kResolutions; ++k)
        ms::audit::add_room_power(scratch[k], r.data.measured.grids[k], grids[k], footprints[s][k], rates);
      gap += target.strike_gap(s, scratch);
    }
    benchmark::DoNotOptimize(gap);
  }
}
BENCHMARK(BM_RoomCandidateClosedForm)->Unit(benchmark::kMillisecond);

// Reference: the same candidate by convolution, one impulse response drawn (one draw of what the closed
// form gives in expectation), each strike's dry rendering convolved, its spectrograms and gap.
void BM_RoomCandidateConvolved(benchmark::State& state) {
  const RoomScoring r;
  const double fs = r.data.measured.sample_rate_hz;
  ms::audit::AuditModel in_room = r.model;
  in_room.room = r.room;
  std::vector<std::vector<float>> dry;
  for (std::size_t s = 0; s < r.data.strike_count(); ++s)
    dry.push_back(ms::render_bank(ms::audit::dry_strike_model(in_room, s, fs), {}, fs, r.data.measured.strikes[s].samples.size()));
  for (auto _ : state) {
    const std::vector<float> h = ms::room_impulse_response(r.room, fs);
    double gap = 0.0;
    for (std::size_t s = 0; s < dry.size(); ++s) {
      std::vector<float> wet = dry[s];
      ms::convolve_overlap_add(wet, h);
      gap += ms::audit::gap_map(r.data.measured.strikes[s].spectra, ms::audit::bark_spectra(wet, r.data.measured.grids)).gap_db;
    }
    benchmark::DoNotOptimize(gap);
  }
}
BENCHMARK(BM_RoomCandidateConvolved)->Unit(benchmark::kMillisecond);

// The repeatability floor alone (one leave-one-strike-out pass of the plain model), as run_audit adds it.
void BM_RepeatabilityFloorTenStrikes(benchmark::State& state) {
  const auto data = ms::audit::make_audit_data(ten_strikes().recordings);
  for (auto _ : state) benchmark::DoNotOptimize(ms::audit::repeatability_floor(data, ms::audit::Recipe{}).floor_db);
}
BENCHMARK(BM_RepeatabilityFloorTenStrikes)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_AuditTenStrikesExtractionOnly(benchmark::State& state) {
  const auto hc = ten_strikes();
  for (auto _ : state) benchmark::DoNotOptimize(ms::audit::make_audit_data(hc.recordings).tracks.size());
}
BENCHMARK(BM_AuditTenStrikesExtractionOnly)->Unit(benchmark::kMillisecond)->Iterations(3);

// Naive reference: each of the 10 leave-one-out folds of one candidate re-analyses its 9 training
// recordings from the audio (what a script around `modalstudy extract` would do), once per candidate.
void BM_AuditNaiveRefoldExtraction(benchmark::State& state) {
  const auto hc = ten_strikes();
  for (auto _ : state) {
    double sum = 0.0;
    for (std::size_t k = 0; k < hc.recordings.size(); ++k) {
      std::vector<ms::audit::Recording> train;
      for (std::size_t s = 0; s < hc.recordings.size(); ++s)
        if (s != k) train.push_back(hc.recordings[s]);
      sum += double(ms::audit::make_audit_data(train).tracks.size());
    }
    benchmark::DoNotOptimize(sum);
  }
}
BENCHMARK(BM_AuditNaiveRefoldExtraction)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
