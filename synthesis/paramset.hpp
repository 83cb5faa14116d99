// Parameter set: one stimulus recipe (stimuli/*.yaml), resolved into everything the renderer needs.
// The model comes from inline modes, a modes CSV, or an analytic object (bar, plate, raw eigenvalues)
// with a material or an explicit damping law. See README "Parameter sets" for every key.
// YAML -> read_recipe -> ParamSetRecipe (paramset_recipe.hpp) -> resolve -> ParamSet -> render_stimulus;
// write_yaml turns a recipe back into YAML.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "synthesis/audio_file.hpp"
#include "synthesis/effects.hpp"
#include "synthesis/excitation.hpp"
#include "synthesis/modal_model.hpp"
#include "synthesis/output_level.hpp"
#include "synthesis/paramset_recipe.hpp"
#include "synthesis/path_confinement.hpp"
#include "synthesis/residual_file.hpp"
#include "synthesis/room_response.hpp"

namespace ms {

// The residual a set adds to its modes (`residual:`), read once when the set is resolved.
struct ResidualUse {
  std::shared_ptr<const ResidualSpectrogram> spectrogram;  // null: the set has no residual
  std::string sha256;                                      // of the file's bytes (in the recipe hash)
  double gain_db = 0.0;
  std::uint64_t seed = 0;
};

struct ParamSet {
  std::string source;            // file it was read from ("" for text)
  double sample_rate_hz = 44100;
  double duration_s = 1.0;
  ModalModel model;              // resolved modes, support damping and doublets applied
  Excitation excitation;
  OutputLevel level;
  Room room;                     // convolved with the rendering (and its residual), before reverb
  Reverb reverb;                 // added after rendering (relative to the direct sound), before noise
  AttackTransient transient;     // likewise
  BackgroundNoise noise;         // added after rendering, before the output level
  ResidualUse residual;          // transferred to the model and added to it, before reverb and transient
  Renderer renderer = Renderer::resonator;
  std::vector<double> bandpass_q;  // renderer bandpass: one Q for all, or one per mode of `model`
  double bandpass_clip = 1.0;      // renderer bandpass: the clipper's level (0: none)
  SampleFormat format = SampleFormat::float32;
  SourceLocation format_where;   // where output.format was written (the file alone when it was not)
  std::string description;       // free text
  std::vector<std::string> warnings;  // e.g. overdamped modes dropped
  std::size_t modes_before_pruning = 0;  // 0 when the set has no `prune`
  std::string recipe_hash;       // SHA-256 of the canonical resolved recipe (hex)
};

// The renderable set a recipe describes: the material looked up, the modes built (inline, from the
// modes CSV, or from the object), support damping, doublets and pruning applied, the hash taken.
// Throws InputError at the key's location for what only resolving finds (an unknown material or hit
// point, a CSV that cannot be used, a doublet split too wide, no modes). Files the recipe names must lie
// inside `confinement`; without one, inside paramset_confinement(the recipe's base_dir).
ParamSet resolve(const ParamSetRecipe& recipe, const Confinement* confinement = nullptr);

// read_recipe + resolve. Reads and resolves a parameter set; `overrides` are "key.path=value" (like --set).
// Throws InputError with file:line:column for every problem a person can make. Files the set names
// (a modes CSV) must lie inside `confinement`; without one, inside paramset_confinement(its folder).
ParamSet load_paramset(const std::string& path, const std::vector<std::string>& overrides = {},
                       const Confinement* confinement = nullptr);
ParamSet parse_paramset(const std::string& yaml_text, const std::string& file_for_errors,
                        const std::string& base_dir, const std::vector<std::string>& overrides = {},
                        const Confinement* confinement = nullptr);

// The canonical text the recipe hash is taken over (resolved values, 17 digits).
std::string canonical_recipe(const ParamSet& p);

}  // namespace ms
