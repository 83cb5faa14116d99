// StimulusCache: hashes first (cheap, catches every bad stimulus before a session starts), samples on
// demand; see stimulus_cache.hpp.
#include "studyapp/core/stimulus_cache.hpp"

#include <filesystem>
#include <set>

#include "studyapp/core/anchor_lowpass.hpp"
#include "studyapp/core/protocol_validator.hpp"
#include "studyapp/core/stimulus_sequence.hpp"
#include "synthesis/audio_file.hpp"
#include "synthesis/bounded_file.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/paramset.hpp"
#include "synthesis/sha256.hpp"
#include "synthesis/stimulus.hpp"
#include "synthesis/yaml_reader.hpp"

#include <yaml-cpp/yaml.h>

namespace ms {

namespace fs = std::filesystem;

namespace {

std::vector<std::string> with(std::vector<std::string> base, const std::vector<std::string>& extra) {
  base.insert(base.end(), extra.begin(), extra.end());
  return base;
}

std::string number_text(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

}  // namespace

StimulusCache::StimulusCache(const Protocol& protocol, std::string cache_dir)
    : protocol_(protocol),
      cache_dir_(std::move(cache_dir)),
      sample_rate_hz_(protocol.sample_rate_hz),
      confinement_(protocol_confinement(protocol)) {
  // Derived stimuli and sequences hash their sources' hashes, so sources come first (the validator
  // rejects cycles; the bound on passes keeps a cycle that slipped through from looping).
  std::set<std::string> pending;
  for (const auto& s : protocol_.stimuli) pending.insert(s.name);
  for (int pass = 0; !pending.empty() && pass <= int(protocol_.stimuli.size()); ++pass)
    for (const auto& s : protocol_.stimuli) {
      if (!pending.count(s.name)) continue;
      switch (s.kind) {
        case StimulusKind::paramset: {
          auto p = std::make_shared<const ParamSet>(
              load_paramset(confined_stimulus_path(protocol_, s, confinement_), s.overrides, &confinement_));
          check_paramset_stimulus(protocol_, s, *p);
          hashes_[s.name] = p->recipe_hash;
          paramsets_[s.name] = std::move(p);
          break;
        }
        case StimulusKind::derived: {
          const auto parent = hashes_.find(s.derive_from.name);
          if (parent == hashes_.end()) continue;  // next pass
          hashes_[s.name] = sha256_hex("lowpass_hz=" + number_text(s.lowpass_hz) + " of " + parent->second);
          break;
        }
        case StimulusKind::sequence: {
          std::vector<SequenceRecipePart> parts;
          for (const SequencePart& part : s.sequence) {
            const auto h = hashes_.find(part.stimulus.name);
            if (h == hashes_.end()) break;
            parts.push_back({h->second, part.onset_s, part.gain_db});
          }
          if (parts.size() < s.sequence.size()) continue;  // next pass
          hashes_[s.name] = sequence_hash(parts, sample_rate_hz_);
          break;
        }
        case StimulusKind::file:
          try {
            hashes_[s.name] = sha256_file_hex(confined_stimulus_path(protocol_, s, confinement_));
          } catch (const InputError& e) {
            if (e.where().file != resolve_protocol_path(protocol_, s.path)) throw;
            stimulus_file_problem(s, e.problem());
          }
          break;
      }
      pending.erase(s.name);
    }
  if (!pending.empty())
    throw InputError(source(*pending.begin()).where, "stimulus '" + *pending.begin() + "' is made from a stimulus "
                                                     "that does not exist or is made from it");
}

const StimulusSource& StimulusCache::source(const std::string& name) const {
  const StimulusSource* s = protocol_.find_stimulus(name);
  if (!s) throw std::out_of_range("StimulusCache: no stimulus named '" + name + "'");
  return *s;
}

const std::string& StimulusCache::hash(const std::string& name) const {
  const auto h = hashes_.find(name);
  if (h == hashes_.end()) throw std::out_of_range("StimulusCache: no stimulus named '" + name + "'");
  return h->second;
}

std::size_t StimulusCache::rendered_count() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return renders_;
}

Samples StimulusCache::lookup_or_render(const std::string& hash, const std::function<std::vector<float>()>& render) {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (const auto m = memory_.find(hash); m != memory_.end()) return m->second;
  }
  const std::string file = cache_dir_.empty() ? "" : (fs::path(cache_dir_) / (hash + ".wav")).string();
  std::shared_ptr<std::vector<float>> samples;
  std::error_code ec;
  if (!file.empty() && fs::exists(file, ec)) {
    try {
      const Audio a = read_audio(file);
      if (a.sample_rate_hz == sample_rate_hz_ && a.channels == 1)
        samples = std::make_shared<std::vector<float>>(a.samples);
    } catch (const InputError&) {
      // A damaged cache entry is rendered again (and rewritten) rather than trusted.
    }
  }
  if (!samples) {
    samples = std::make_shared<std::vector<float>>(render());
    if (!file.empty()) {
      fs::create_directories(cache_dir_, ec);
      if (!ec) write_wav(file, Audio{sample_rate_hz_, 1, *samples}, SampleFormat::float32);  // atomic
    }
    const std::lock_guard<std::mutex> lock(mutex_);
    ++renders_;
  }
  const std::lock_guard<std::mutex> lock(mutex_);
  return memory_.emplace(hash, std::move(samples)).first->second;  // first writer wins
}

Samples StimulusCache::samples(const std::string& name) { return make(name); }

Samples StimulusCache::make(const std::string& name) {
  const StimulusSource& s = source(name);
  const std::string& h = hash(name);
  switch (s.kind) {
    case StimulusKind::paramset:
      return lookup_or_render(h, [&] { return render_stimulus(*paramsets_.at(name)).audio.samples; });
    case StimulusKind::derived:
      return lookup_or_render(h, [&] {
        const Samples parent = make(s.derive_from.name);
        return lowpass_anchor(*parent, sample_rate_hz_, s.lowpass_hz);
      });
    case StimulusKind::file:
      return lookup_or_render(h, [&] { return read_recording_stimulus(protocol_, s, confinement_); });
    case StimulusKind::sequence:
      return lookup_or_render(h, [&] {
        std::vector<Samples> parts;  // held while mixing
        std::vector<SequenceStrike> strikes;
        for (const SequencePart& part : s.sequence) {
          parts.push_back(make(part.stimulus.name));
          strikes.push_back({parts.back().get(), part.onset_s, part.gain_db});
        }
        return mix_sequence(strikes, sample_rate_hz_, s.where, s.name);
      });
  }
  return nullptr;
}

void StimulusCache::prepare_all(const std::function<void(std::size_t, std::size_t, const std::string&)>& progress) {
  const std::size_t total = protocol_.stimuli.size();
  std::size_t done = 0;
  for (const auto& s : protocol_.stimuli) {
    make(s.name);
    if (progress) progress(++done, total, s.name);
  }
}

std::optional<double> StimulusCache::parameter_value(const std::string& name, const std::string& key) const {
  const StimulusSource& s = source(name);
  if (s.kind != StimulusKind::paramset) return std::nullopt;
  const std::string path = resolve_protocol_path(protocol_, s.path);
  try {
    YAML::Node node = YAML::Load(read_bounded_file(path, kYamlFileLimit));
    apply_overrides(node, s.overrides);
    for (std::size_t start = 0;;) {  // walk the dotted path
      const auto dot = key.find('.', start);
      if (!node.IsMap()) return std::nullopt;
      node = node[key.substr(start, dot - start)];
      if (!node) return std::nullopt;
      if (dot == std::string::npos) break;
      start = dot + 1;
    }
    if (!node.IsScalar()) return std::nullopt;
    return node.as<double>();
  } catch (const std::exception&) {  // YAML or conversion errors: the set itself was validated already
    return std::nullopt;
  }
}

std::string StimulusCache::hash_with(const std::string& name, const std::vector<std::string>& extra) {
  const StimulusSource& s = source(name);
  if (s.kind != StimulusKind::paramset)
    throw InputError(s.where, "stimulus '" + name + "' is not a parameter set, so its parameters cannot change");
  return load_paramset(confined_stimulus_path(protocol_, s, confinement_), with(s.overrides, extra), &confinement_).recipe_hash;
}

Samples StimulusCache::samples_with(const std::string& name, const std::vector<std::string>& extra) {
  if (extra.empty()) return samples(name);
  const StimulusSource& s = source(name);
  if (s.kind != StimulusKind::paramset)
    throw InputError(s.where, "stimulus '" + name + "' is not a parameter set, so its parameters cannot change");
  // Loading resolves the recipe (and its hash); rendering happens only on a cache miss.
  const ParamSet p = load_paramset(confined_stimulus_path(protocol_, s, confinement_), with(s.overrides, extra), &confinement_);
  return lookup_or_render(p.recipe_hash, [&] { return render_stimulus(p).audio.samples; });
}

}  // namespace ms
