#include "analysis/audit/strikes.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <thread>

namespace ms::audit {

MeasuredStrikes prepare_strikes(const std::vector<Recording>& recordings, const StrikeOptions& options) {
  if (recordings.empty()) throw AuditError("no recordings to audit");
  MeasuredStrikes out;
  out.sample_rate_hz = recordings.front().sample_rate_hz;
  for (const Recording& r : recordings)
    if (r.sample_rate_hz != out.sample_rate_hz)
      throw AuditError(r.name + ": sample rate " + std::to_string(std::lround(r.sample_rate_hz)) + " Hz differs from " +
                       recordings.front().name + "'s " + std::to_string(std::lround(out.sample_rate_hz)) +
                       " Hz; resample the recordings to one rate first");
  ExtractOptions extract;
  extract.skip_contact_s = options.skip_contact_s;
  extract.max_attack_skip_s = options.max_attack_skip_s;
  extract.max_dynamic_range_db = options.dynamic_range_db;
  std::size_t common = std::size_t(options.max_duration_s * out.sample_rate_hz);
  for (const Recording& r : recordings)
    if (auto problem = recording_problem(r.samples, r.sample_rate_hz)) throw AuditError(r.name + ": " + *problem);
  // Each strike's extraction stands alone: they run on the machine's cores (FFTW's planner is locked in
  // synthesis/fft; the results do not depend on the order).
  std::vector<ExtractedFeatures> features(recordings.size());
  std::vector<std::exception_ptr> failed(recordings.size());
  std::atomic<std::size_t> next{0};
  const auto work = [&] {
    for (std::size_t i; (i = next++) < recordings.size();) {
      try {
        features[i] = extract_features(recordings[i].samples, recordings[i].sample_rate_hz, extract);
      } catch (...) {
        failed[i] = std::current_exception();
      }
    }
  };
  const std::size_t threads = std::min<std::size_t>(std::max(1u, std::thread::hardware_concurrency()), recordings.size());
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
  for (std::size_t i = 0; i < recordings.size(); ++i) {
    const Recording& r = recordings[i];
    Strike s;
    s.name = r.name;
    s.features = std::move(features[i]);
    if (s.features.modes.empty()) throw AuditError(r.name + ": no modes stand above the noise floor (silence?)");
    s.attack_noise_s = std::max(0.0, s.features.attack_skip_s - options.skip_contact_s);
    const std::size_t onset = std::size_t(std::lround(s.features.onset_s * r.sample_rate_hz));
    s.samples.assign(r.samples.begin() + std::ptrdiff_t(std::min(onset, r.samples.size())), r.samples.end());
    common = std::min(common, s.samples.size());
    out.strikes.push_back(std::move(s));
  }
  if (double(common) < options.min_duration_s * out.sample_rate_hz)
    throw AuditError("recordings last less than " + std::to_string(options.min_duration_s) +
                     " s after the strike; an audit needs the decay");
  out.grids = make_grids(out.sample_rate_hz, common);
  for (Strike& s : out.strikes) {
    s.samples.resize(common);
    s.spectra = bark_spectra(s.samples, out.grids);
  }
  return out;
}

}  // namespace ms::audit
