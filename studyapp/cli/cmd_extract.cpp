// modalstudy extract WAV... [--json] [-o FEATURES.csv [--errors]] [--channel N] [--thorough]
//                            [--object-out OBJECT.yaml [--specific-modulus E/RHO] [--material ID]]
// Modal features (freq_hz, decay_per_s, amp at the onset) of impact recordings; see
// analysis/feature_extraction.hpp. Every file is checked before anything is written. --json adds every
// mode's error bars (Cramer-Rao standard deviations, analysis/mode_precision.hpp). --object-out writes
// one recording's modes as a parameter set with an `eigenvalues` object (measured_object.hpp): the
// object `modalstudy estimate --object` needs when there is no model of the geometry.
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "analysis/audit/parallel_indices.hpp"
#include "analysis/extraction/feature_extraction.hpp"
#include "analysis/extraction/measured_object.hpp"
#include "studyapp/cli/commands.hpp"
#include "studyapp/cli/stats_output.hpp"
#include "synthesis/atomic_file.hpp"
#include "synthesis/audio_file.hpp"
#include "synthesis/csv.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/paramset.hpp"

namespace ms::cli {

void register_extract(CLI::App& app) {
  struct Options {
    double skip_contact_ms = 0.5;  // real strikes have a contact; 0 for ideal impulses
    double attack_skip_ms = 20.0;  // noise at the attack the modes cannot explain; 0 turns it off
    std::vector<std::string> inputs;
    std::string output;
    std::string object_out;
    MeasuredObjectOptions object;
    int channel = -1;
    bool json = false;
    bool thorough = false;
    bool errors = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* cmd = app.add_subcommand("extract", "Extract modal features (f, d, amp) from impact recordings");
  cmd->add_option("wav", opt->inputs, "Recordings (WAV/FLAC/AIFF)")->required();
  CLI::Option* output = cmd->add_option("-o,--output", opt->output, "Write FEATURES.csv (sound,freq_hz,decay_per_s,amp)");
  cmd->add_option("--channel", opt->channel, "0-based channel to analyse (default: mix to mono)")
      ->check(CLI::Validator(
          [](std::string& v) {
            return v.rfind('-', 0) == 0 ? std::string("must be 0 or more (0-based; leave --channel out to mix to mono)")
                                        : std::string();
          },
          "N >= 0"));
  cmd->add_option("--skip-contact-ms", opt->skip_contact_ms,
                  "Start fitting this long after the onset (the strike's contact is not modal); "
                  "amplitudes are extrapolated back to the onset (default 0.5; 0 for ideal impulses)")
      ->check(CLI::Range(0.0, 20.0));
  cmd->add_option("--max-attack-skip-ms", opt->attack_skip_ms,
                  "Where the first fit leaves noise at the attack that no mode explains (a burst, a long "
                  "contact), fit again from after it, up to this long after the onset (default 20; 0: off)")
      ->check(CLI::Range(0.0, 100.0));
  cmd->add_flag("--json", opt->json, "Print one JSON object with every sound's modes and their error bars");
  cmd->add_flag("--errors", opt->errors,
                "Add each mode's error bars (Cramer-Rao standard deviations) to the CSV: freq_sd_hz, "
                "decay_sd_per_s, amp_sd (empty where the data do not determine the value)")
      ->needs(output);
  cmd->add_flag("--thorough", opt->thorough,
                "Second start for crowded, heavily damped modes below 700 Hz (kept when the penalised fit "
                "improves): a few % more modes for ~70 % more time");
  CLI::Option* object_out =
      cmd->add_option("--object-out", opt->object_out,
                      "Write the (one) recording's modes as a parameter set with an eigenvalues object "
                      "(lambda0 = omega^2 / E/rho, gains the amplitudes): a measured object for "
                      "`estimate --object` when the geometry has no model");
  cmd->add_option("--specific-modulus", opt->object.specific_modulus_m2_s2,
                  "E/rho [m^2/s^2] the object's eigenvalues are written for (default: the material's)")
      ->check(CLI::PositiveNumber)
      ->needs(object_out);
  cmd->add_option("--material", opt->object.material,
                  "Library material the object set renders with (default ren2013/metal)")
      ->needs(object_out);
  cmd->callback([opt] {
    if (!opt->object_out.empty() && opt->inputs.size() != 1)
      throw InputError(SourceLocation{"--object-out", 0, 0},
                       "needs exactly one recording, not " + std::to_string(opt->inputs.size()));
    // The recordings are read and fitted on the machine's cores, each into its own slot; a bad file
    // stops the command with the first problem in the order given, as one after another would.
    std::vector<std::pair<std::string, ExtractedFeatures>> results(opt->inputs.size());
    std::vector<double> durations_s(opt->inputs.size(), 0.0);
    audit::parallel_indices(opt->inputs.size(), [&](std::size_t i) {
      const std::string& path = opt->inputs[i];
      const Audio audio = read_audio(path);
      if (opt->channel >= audio.channels)
        throw InputError(SourceLocation{path, 0, 0}, "--channel " + std::to_string(opt->channel) +
                                                         " but the file has " + std::to_string(audio.channels) +
                                                         " channel(s)");
      const std::vector<float> x = mono(audio, opt->channel);
      durations_s[i] = double(x.size()) / audio.sample_rate_hz;
      if (auto problem = recording_problem(x, audio.sample_rate_hz))
        throw InputError(SourceLocation{path, 0, 0}, *problem);
      ExtractOptions options;
      options.skip_contact_s = opt->skip_contact_ms * 1e-3;
      options.max_attack_skip_s = opt->attack_skip_ms * 1e-3;
      options.low_band_restart = opt->thorough;
      ExtractedFeatures f = extract_features(x, audio.sample_rate_hz, options);
      if (f.modes.empty()) throw InputError(SourceLocation{path, 0, 0}, "no modes found above the noise floor");
      results[i] = {std::filesystem::path(path).stem().string(), std::move(f)};
    });
    const double duration_s = durations_s.empty() ? 0.0 : durations_s.front();  // --object-out: one recording
    std::string object_yaml;
    if (!opt->object_out.empty()) {
      const auto& [name, f] = results.front();
      opt->object.description = "Measured object: the modes of " + opt->inputs.front() +
                                " (modalstudy extract --object-out)";
      try {
        object_yaml = write_yaml(measured_object_recipe(f.modes, f.sample_rate_hz, duration_s, opt->object));
      } catch (const std::invalid_argument& e) {
        throw InputError(SourceLocation{"--material", 0, 0}, e.what());
      }
      try {  // the set must read and resolve before it is written
        const std::filesystem::path dir = std::filesystem::path(opt->object_out).parent_path();
        parse_paramset(object_yaml, opt->object_out, dir.empty() ? "." : dir.string());
      } catch (const InputError& e) {
        throw InputError(SourceLocation{opt->object_out, 0, 0}, e.problem());
      }
    }
    if (!opt->output.empty()) {
      // 10 significant digits; empty where the data do not determine the value (an infinite bound).
      auto g10 = [](double v) {
        if (!std::isfinite(v)) return std::string();
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.10g", v);
        return std::string(buf);
      };
      std::vector<std::string> header{"sound", "freq_hz", "decay_per_s", "amp"};
      if (opt->errors) header.insert(header.end(), {"freq_sd_hz", "decay_sd_per_s", "amp_sd"});
      std::string csv = csv::line(header);
      for (const auto& [name, f] : results)
        for (std::size_t k = 0; k < f.modes.size(); ++k) {
          const Mode& m = f.modes[k];
          std::vector<std::string> cells{name, g10(m.freq_hz), g10(m.decay_per_s), g10(m.amp)};
          if (opt->errors) {
            const ModePrecision& p = f.precision[k];
            cells.insert(cells.end(), {g10(p.freq_sd_hz), g10(p.decay_sd_per_s), g10(p.amp_sd)});
          }
          csv += csv::line(cells);
        }
      write_file_atomically(opt->output, csv);
    }
    if (!object_yaml.empty()) write_file_atomically(opt->object_out, object_yaml);
    if (opt->json) {
      nlohmann::json sounds = nlohmann::json::array();
      for (const auto& [name, f] : results) {
        nlohmann::json modes = nlohmann::json::array();
        // Error bars: Cramer-Rao standard deviations; null where the data do not determine the value.
        const auto sd = num_json;
        for (std::size_t k = 0; k < f.modes.size(); ++k) {
          const Mode& m = f.modes[k];
          const ModePrecision& p = f.precision[k];
          modes.push_back({{"freq_hz", m.freq_hz},
                           {"decay_per_s", m.decay_per_s},
                           {"amp", m.amp},
                           {"freq_sd_hz", sd(p.freq_sd_hz)},
                           {"decay_sd_per_s", sd(p.decay_sd_per_s)},
                           {"amp_sd", sd(p.amp_sd)}});
        }
        sounds.push_back({{"sound", name},
                          {"sample_rate", f.sample_rate_hz},
                          {"onset_s", f.onset_s},
                          {"fit_start_s", f.attack_skip_s},
                          {"noise_floor_db", f.noise_floor_db},
                          {"modes", modes}});
      }
      std::cout << nlohmann::json{{"sounds", sounds}}.dump() << "\n";
    } else {
      for (const auto& [name, f] : results)
        std::cout << name << ": " << f.modes.size() << " modes, onset " << f.onset_s << " s, noise floor "
                  << f.noise_floor_db << " dB\n";
    }
  });
}

}  // namespace ms::cli
