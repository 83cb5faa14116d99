// `material: {file: X.yaml}` in a parameter set: a material file (material_file.hpp) beside the
// library ids, relative to the set's folder and inside the set's confinement.
#include <gtest/gtest.h>

#include "support/test_util.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/material.hpp"
#include "synthesis/material_file.hpp"
#include "synthesis/paramset.hpp"

using namespace ms;

namespace {

std::string bar_set(const std::string& material_line) {
  return "sample_rate: 44100\nduration_s: 0.5\n"
         "object: {type: bar, length_m: 0.25, thickness_m: 0.012, hit_position: 0.1}\n" +
         material_line + "\nexcitation: {type: raised_cosine, contact_s: 0.0005}\n";
}

std::string load_error(const std::string& path) {
  try {
    load_paramset(path);
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line";
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ParamsetMaterialFile, AFileOfALibraryMaterialRendersLikeItsId) {
  test::TempDir dir;
  for (const char* id : {"ren2013/wood", "sterling2019/steel"}) {
    dir.write("materials/m.yaml", material_file_yaml(*find_material(id)));
    const ParamSet by_id = load_paramset(dir.write("by_id.yaml", bar_set(std::string("material: ") + id)));
    const ParamSet by_file = load_paramset(dir.write("by_file.yaml", bar_set("material: {file: materials/m.yaml}")));
    ASSERT_FALSE(by_id.model.modes.empty());
    EXPECT_EQ(by_file.recipe_hash, by_id.recipe_hash) << id;
    EXPECT_EQ(by_file.model.modes.size(), by_id.model.modes.size()) << id;
  }
}

TEST(ParamsetMaterialFile, HybridAndOverridesApplyToAFileMaterial) {
  test::TempDir dir;
  dir.write("m.yaml", material_file_yaml(*find_material("sterling2019/wood")));
  const std::string with_file = dir.write("a.yaml", bar_set("material: {file: m.yaml}\ndamping_law: hybrid"));
  const std::string with_id = dir.write("b.yaml", bar_set("material: sterling2019/wood\ndamping_law: hybrid"));
  EXPECT_EQ(load_paramset(with_file).recipe_hash, load_paramset(with_id).recipe_hash);
  EXPECT_EQ(load_paramset(with_file, {"amp_scale=2"}).recipe_hash, load_paramset(with_id, {"amp_scale=2"}).recipe_hash);
  EXPECT_NE(load_paramset(with_file, {"amp_scale=2"}).recipe_hash, load_paramset(with_file).recipe_hash);
  // A Ren material has no hybrid fit, from a file as from the library.
  dir.write("ren.yaml", material_file_yaml(*find_material("ren2013/metal")));
  EXPECT_NE(load_error(dir.write("c.yaml", bar_set("material: {file: ren.yaml}\ndamping_law: hybrid")))
                .find("c.yaml:5:14: damping_law: ren2013/metal has no hybrid fit"),
            std::string::npos);
}

TEST(ParamsetMaterialFile, AnEstimatedMaterialChangesTheSound) {
  test::TempDir dir;
  Material m = *find_material("ren2013/wood");
  m.id = "estimated/spoon";
  m.rayleigh.alpha1 *= 2.0;
  dir.write("spoon.yaml", material_file_yaml(m));
  const ParamSet estimated = load_paramset(dir.write("a.yaml", bar_set("material: {file: spoon.yaml}")));
  const ParamSet wood = load_paramset(dir.write("b.yaml", bar_set("material: ren2013/wood")));
  ASSERT_EQ(estimated.model.modes.size(), wood.model.modes.size());
  EXPECT_NE(estimated.recipe_hash, wood.recipe_hash);
  // d = (alpha1 + alpha2 lambda)/2: doubling alpha1 adds alpha1/2 to every decay.
  EXPECT_NEAR(estimated.model.modes[0].decay_per_s - wood.model.modes[0].decay_per_s, 2.1364 / 2, 1e-9);
}

TEST(ParamsetMaterialFile, MistakesNameTheRightFileAndPlace) {
  test::TempDir dir;
  EXPECT_EQ(load_error(dir.write("a.yaml", bar_set("material: {fil: m.yaml}"))),
            dir.file("a.yaml") + ":4:12: unknown key 'material.fil' (did you mean 'file'?)");
  EXPECT_EQ(load_error(dir.write("b.yaml", bar_set("material: {}"))),
            dir.file("b.yaml") + ":4:11: material: expected a library id or {file: MATERIAL.yaml}");
  const std::string missing = load_error(dir.write("c.yaml", bar_set("material: {file: none.yaml}")));
  EXPECT_EQ(missing.rfind(dir.file("c.yaml") + ":4:18: material.file: cannot use '", 0), 0u) << missing;
  // A mistake inside the material file names the material file, its line and column.
  dir.write("bad.yaml", "id: x\nrayleigh: {alpha1_per_s: 1, alpha2_s: -2}\nspecific_modulus_m2_s2: 1\namp_scale: 1\n");
  EXPECT_EQ(load_error(dir.write("d.yaml", bar_set("material: {file: bad.yaml}"))),
            dir.file("bad.yaml") + ":2:39: rayleigh.alpha2_s: must not be negative, got -2");
  // Outside the set's folder: refused like a modes CSV.
  test::TempDir other;
  other.write("m.yaml", material_file_yaml(*find_material("ren2013/wood")));
  const std::string outside = load_error(dir.write("e.yaml", bar_set("material: {file: " + other.file("m.yaml") + "}")));
  EXPECT_NE(outside.find(":4:18: material.file: path '"), std::string::npos) << outside;
  EXPECT_NE(outside.find("is outside the parameter set's folder"), std::string::npos) << outside;
  // ... and allowed with an unrestricted confinement (--allow-outside).
  const Confinement anywhere = Confinement::anywhere();
  EXPECT_NO_THROW(load_paramset(dir.file("e.yaml"), {}, &anywhere));
}

TEST(ParamsetMaterialFile, ASetInsideStimuliMayUseAMaterialAnywhereInStimuli) {
  test::TempDir dir;
  dir.write("stimuli/materials/spoon.yaml", material_file_yaml(*find_material("ren2013/glass")));
  const std::string set = dir.write("stimuli/bar/spoon.yaml", bar_set("material: {file: ../materials/spoon.yaml}"));
  EXPECT_EQ(load_paramset(set).model.modes.size(),
            load_paramset(dir.write("stimuli/bar/glass.yaml", bar_set("material: ren2013/glass"))).model.modes.size());
}
