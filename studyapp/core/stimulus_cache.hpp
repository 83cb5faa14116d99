// The stimuli of a protocol as sample buffers: parameter sets rendered by the embedded synthesizer,
// derived low-pass anchors, recordings, sequences of other stimuli. Each is identified by a hash of
// what produced it (the recipe hash for parameter sets) and cached in memory and on disk
// (CACHE_DIR/<hash>.wav), so a stimulus is rendered once per recipe, whatever protocol or session asks
// for it.
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "studyapp/core/protocol.hpp"
#include "studyapp/core/stimulus_checks.hpp"
#include "synthesis/paramset.hpp"
#include "synthesis/path_confinement.hpp"

namespace ms {

using Samples = std::shared_ptr<const std::vector<float>>;  // mono, at the protocol's sample rate

class StimulusCache {
 public:
  // cache_dir "" keeps rendered stimuli in memory only. Loads every parameter set (with overrides) to
  // compute the hashes; throws InputError (file:line:col) for the first stimulus that cannot be made.
  StimulusCache(const Protocol& protocol, std::string cache_dir);

  const std::map<std::string, std::string>& hashes() const { return hashes_; }  // name -> hash
  const std::string& hash(const std::string& name) const;

  // Renders (or loads from the cache) one stimulus. Thread-safe; throws InputError for a recording
  // that cannot be read or has another sample rate than the protocol.
  Samples samples(const std::string& name);
  // Renders every stimulus the protocol names, calling progress(done, total, name) after each.
  void prepare_all(const std::function<void(std::size_t, std::size_t, const std::string&)>& progress = {});

  // A parameter-set stimulus with extra "key=value" overrides (adjust sliders, staircase levels).
  // Cached by the resulting recipe hash like any other stimulus.
  Samples samples_with(const std::string& name, const std::vector<std::string>& extra_overrides);
  std::string hash_with(const std::string& name, const std::vector<std::string>& extra_overrides);

  // The value a parameter-set stimulus gives a dotted key (e.g. damping.alpha1) as written in its file
  // with the protocol's overrides; nullopt when the key is not written (e.g. it comes from a material).
  std::optional<double> parameter_value(const std::string& name, const std::string& key) const;

  double sample_rate_hz() const { return sample_rate_hz_; }
  std::size_t rendered_count() const;  // renders done by this object (cache misses), for tests

 private:
  Samples make(const std::string& name);
  Samples lookup_or_render(const std::string& hash, const std::function<std::vector<float>()>& render);
  const StimulusSource& source(const std::string& name) const;

  const Protocol& protocol_;
  std::string cache_dir_;
  double sample_rate_hz_;
  Confinement confinement_;  // protocol_confinement(protocol): every file the stimuli reach
  std::map<std::string, std::string> hashes_;
  std::map<std::string, std::shared_ptr<const ParamSet>> paramsets_;  // loaded once, by stimulus name
  mutable std::mutex mutex_;
  std::map<std::string, Samples> memory_;  // hash -> samples
  std::size_t renders_ = 0;
};


}  // namespace ms
