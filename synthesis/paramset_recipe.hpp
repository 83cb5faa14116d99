// A parameter set as written (stimuli/*.yaml): every key of the format as a typed field, before any
// material is looked up or any mode is built. read_recipe checks every value and range a person can
// get wrong (file:line:column); resolve (paramset.hpp) turns a recipe into the renderable ParamSet;
// write_yaml writes a recipe back as YAML that reads to the same recipe.
//
// A new key is one field here, one line in read_recipe and one line in write_yaml.
#pragma once
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "synthesis/audio_file.hpp"
#include "synthesis/damping_law.hpp"
#include "synthesis/effects.hpp"
#include "synthesis/excitation.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/masking_pruning.hpp"
#include "synthesis/modal_model.hpp"
#include "synthesis/name_table.hpp"
#include "synthesis/output_level.hpp"
#include "synthesis/renderer_choice.hpp"
#include "synthesis/room_response.hpp"

namespace ms {

enum class ObjectType { bar, plate, eigenvalues };
inline constexpr NameTable<ObjectType, 3> kObjectTypeNames{
    {{ObjectType::bar, "bar"}, {ObjectType::plate, "plate"}, {ObjectType::eigenvalues, "eigenvalues"}}};

// Which of a library material's published fits `damping_law:` picks.
enum class MaterialFit { rayleigh, hybrid };
inline constexpr NameTable<MaterialFit, 2> kMaterialFitNames{
    {{MaterialFit::rayleigh, "rayleigh"}, {MaterialFit::hybrid, "hybrid"}}};

struct HitPoint {
  std::string name;
  double position = 0.0;  // bar: fraction of the length; plate: fraction of the radius
};

// `object:` an analytic object whose eigenvalues (for E/rho = 1) and mode shapes give the modes.
struct ObjectRecipe {
  ObjectType type = ObjectType::bar;
  double length_m = 0.0;       // bar
  double radius_m = 0.0;       // plate
  double thickness_m = 0.0;    // bar, plate
  double poisson = 0.33;       // plate
  double hit_position = 0.1;   // bar: the default hit, fraction of the length
  double hit_radius = 0.3;     // plate: the default hit, fraction of the radius
  std::vector<HitPoint> hit_points;  // bar, plate: named hits beside "default"
  std::size_t max_modes = 2000;
  std::vector<double> lambda0;  // eigenvalues
  std::vector<double> gains;    // eigenvalues: one per lambda0 (empty: all 1)
};

struct HitGains {
  std::string name;
  std::vector<double> gains;  // one per mode
};

// `residual:` a residual file (MATERIAL.residual.msr, residual_file.hpp) transferred to this set's
// object and added to its modes (residual_transfer.hpp).
struct ResidualRecipe {
  std::string file;        // path as written, relative to origin.base_dir
  double gain_db = 0.0;    // on the transferred residual's amplitude
  std::uint64_t seed = 0;  // Griffin-Lim's initial phases
};

struct PruneRecipe {
  PruneOptions options;
  std::optional<std::size_t> keep;  // the first `keep` modes in the ordering (all when absent)
};

// Where a recipe came from: the file (for messages), the folder its relative paths start from, and
// where each key was written (for the errors only resolve can find). Not part of what the recipe says:
// write_yaml leaves it out.
struct RecipeOrigin {
  std::string file;
  std::string base_dir = ".";
  std::map<std::string, SourceLocation> written_at;  // dotted key path -> location

  SourceLocation where(const std::string& key_path) const;
  [[noreturn]] void fail(const std::string& key_path, const std::string& problem) const;
};

struct ParamSetRecipe {
  std::string description;
  double sample_rate_hz = 44100;
  double duration_s = 1.0;
  // The model: exactly one of inline modes, a modes CSV and an object.
  std::vector<Mode> modes;
  std::string modes_csv;              // path as written, relative to origin.base_dir
  std::optional<ObjectRecipe> object;
  std::vector<HitGains> hit_gains;    // modes models: named gain sets
  // Object models: a material (library id or file) and/or an explicit law and stiffness.
  std::string material;               // library id
  std::string material_file;          // path as written, relative to origin.base_dir
  MaterialFit damping_law = MaterialFit::rayleigh;
  std::optional<DampingLaw> damping;
  std::optional<double> specific_modulus_m2_s2;  // default: the material's
  std::optional<double> fundamental_hz;          // sets the stiffness instead of E/rho
  std::optional<double> amp_scale;               // default: the material's (1 for modes)
  double stiffness_scale = 1.0;
  double size_scale = 1.0;
  std::string hit;                    // hit point name ("" : the default)
  Excitation excitation;
  std::optional<SupportDamping> support_damping;
  std::optional<Doublets> doublets;
  BackgroundNoise noise;
  Room room;
  Reverb reverb;
  AttackTransient transient;
  std::optional<PruneRecipe> prune;
  std::optional<ResidualRecipe> residual;
  Renderer renderer = Renderer::resonator;
  std::optional<BandpassRecipe> bandpass;  // exactly with renderer: bandpass
  OnsetPhase phase = OnsetPhase::sine;
  OutputLevel level{LevelMode::peak, -1.0, 0.005};
  SampleFormat format = SampleFormat::float32;
  RecipeOrigin origin;
};

// The target level `level.normalize` implies when `level.target_dbfs` is not written.
double default_target_dbfs(LevelMode mode);

// Reads a parameter set; `overrides` are "key.path=value" (like --set), applied before reading.
// Throws InputError with file:line:column for every problem a person can make in the text itself.
ParamSetRecipe read_recipe(const std::string& yaml_text, const std::string& file_for_errors,
                           const std::string& base_dir, const std::vector<std::string>& overrides = {});
ParamSetRecipe read_recipe_file(const std::string& path, const std::vector<std::string>& overrides = {});

// The recipe as YAML (numbers exact in their shortest form; optional keys at their defaults left
// out), which read_recipe reads back to the same recipe: writing that again gives the same text.
std::string write_yaml(const ParamSetRecipe& recipe);

}  // namespace ms
