// Material files: every library material survives writing and reading exactly, and each mistake a
// person can make in one is a single file:line:column line.
#include <gtest/gtest.h>

#include "support/test_util.hpp"
#include "synthesis/input_error.hpp"
#include "synthesis/material_file.hpp"

using namespace ms;

namespace {

void expect_same_law(const DampingLaw& a, const DampingLaw& b, const std::string& what) {
  EXPECT_EQ(a.kind, b.kind) << what;
  EXPECT_EQ(a.alpha1, b.alpha1) << what;
  EXPECT_EQ(a.alpha2, b.alpha2) << what;
  EXPECT_EQ(a.alpha3, b.alpha3) << what;
  EXPECT_EQ(a.loss_factor, b.loss_factor) << what;
}

void expect_same_material(const Material& a, const Material& b) {
  EXPECT_EQ(a.id, b.id);
  EXPECT_EQ(a.source, b.source) << a.id;
  expect_same_law(a.rayleigh, b.rayleigh, a.id + " rayleigh");
  ASSERT_EQ(a.hybrid.has_value(), b.hybrid.has_value()) << a.id;
  if (a.hybrid) expect_same_law(*a.hybrid, *b.hybrid, a.id + " hybrid");
  EXPECT_EQ(a.specific_modulus_m2_s2, b.specific_modulus_m2_s2) << a.id;
  EXPECT_EQ(a.modulus_source, b.modulus_source) << a.id;
  EXPECT_EQ(a.amp_scale, b.amp_scale) << a.id;
}

const char* kValid = R"(id: estimated/spoon
rayleigh: {alpha1_per_s: 2.5, alpha2_s: 3e-6}
specific_modulus_m2_s2: 6.5e5
amp_scale: 2e-6
)";

std::string error_of(const std::string& text) {
  try {
    parse_material_file(text, "m.yaml");
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line";
    return e.what();
  }
  return "";
}

}  // namespace

TEST(MaterialFile, EveryLibraryMaterialRoundTripsExactly) {
  ASSERT_EQ(material_library().size(), 11u);
  test::TempDir dir;
  for (const Material& m : material_library()) {
    const std::string path = dir.write("m.yaml", material_file_yaml(m));
    expect_same_material(read_material_file(path), m);
  }
}

TEST(MaterialFile, AwkwardTextAndNumbersRoundTrip) {
  Material m;
  m.id = "null";
  m.source = "Ren: {a, b} # \"quoted\" 'and' more";
  m.modulus_source = "true";
  m.rayleigh = {DampingKind::rayleigh, 0.1 + 0.2, 1.0 / 3.0 * 1e-7, 1.0, 0.0};
  m.hybrid = DampingLaw{DampingKind::hybrid, 1e-300, 5e-324, 0.97800000000000001, 0.0};
  m.specific_modulus_m2_s2 = 123456789.123456789;
  m.amp_scale = 1.7976931348623157e308;
  expect_same_material(parse_material_file(material_file_yaml(m), "m.yaml"), m);
}

TEST(MaterialFile, MinimalFileReadsWithDefaults) {
  const Material m = parse_material_file(kValid, "m.yaml");
  EXPECT_EQ(m.id, "estimated/spoon");
  EXPECT_EQ(m.rayleigh.kind, DampingKind::rayleigh);
  EXPECT_EQ(m.rayleigh.alpha1, 2.5);
  EXPECT_EQ(m.rayleigh.alpha2, 3e-6);
  EXPECT_FALSE(m.hybrid.has_value());
  EXPECT_EQ(m.specific_modulus_m2_s2, 6.5e5);
  EXPECT_EQ(m.amp_scale, 2e-6);
  EXPECT_EQ(m.source, "");
}

TEST(MaterialFile, MistakesAreOneLineWithThePosition) {
  EXPECT_EQ(error_of(""), "m.yaml:1:1: empty material file");
  EXPECT_EQ(error_of("- 1\n"), "m.yaml:1:1: a material file is a map of keys (id, rayleigh, specific_modulus_m2_s2, amp_scale, ...)");
  EXPECT_EQ(error_of(std::string(kValid) + "amp_scal: 1\n"), "m.yaml:5:1: unknown key 'amp_scal' (did you mean 'amp_scale'?)");
  EXPECT_EQ(error_of(std::string(kValid) + "amp_scale: 1\n"),
            "m.yaml:5:1: duplicate key 'amp_scale' (first at line 4, column 1)");
  EXPECT_EQ(error_of("id: x\nrayleigh: {alpha1_per_s: 1, alpha2_s: 1e-7}\namp_scale: 1\n"),
            "m.yaml:1:1: missing 'specific_modulus_m2_s2'");
  EXPECT_EQ(error_of("id: x\nrayleigh: {alpha1_per_s: 1}\nspecific_modulus_m2_s2: 1\namp_scale: 1\n"),
            "m.yaml:2:11: rayleigh: missing 'alpha2_s'");
  EXPECT_EQ(error_of("id: x\nrayleigh: {alpha1_per_s: -1, alpha2_s: 1e-7}\nspecific_modulus_m2_s2: 1\namp_scale: 1\n"),
            "m.yaml:2:26: rayleigh.alpha1_per_s: must not be negative, got -1");
  EXPECT_EQ(error_of("id: x\nrayleigh: {alpha1_per_s: 1, alpha2_s: .nan}\nspecific_modulus_m2_s2: 1\namp_scale: 1\n"),
            "m.yaml:2:39: rayleigh.alpha2_s: '.nan' is not a finite number");
  EXPECT_EQ(error_of("id: x\nrayleigh: {alpha1_per_s: 1, alpha2_s: 1e-7}\nspecific_modulus_m2_s2: 0\namp_scale: 1\n"),
            "m.yaml:3:25: specific_modulus_m2_s2: must be greater than 0, got 0");
  EXPECT_EQ(error_of(std::string(kValid) + "hybrid: {alpha1_per_s: 1, alpha2: 1e-7, alpha3: 0}\n"),
            "m.yaml:5:49: hybrid.alpha3: must be greater than 0, got 0");
  EXPECT_EQ(error_of(std::string(kValid) + "hybrid: {alpha1_per_s: 1, alpha2: 1e-7, alpha4: 1}\n"),
            "m.yaml:5:41: unknown key 'hybrid.alpha4' (did you mean 'alpha2'?)");
  EXPECT_EQ(error_of("id: [x]\nrayleigh: {alpha1_per_s: 1, alpha2_s: 1e-7}\nspecific_modulus_m2_s2: 1\namp_scale: 1\n"),
            "m.yaml:1:5: id: expected text");
  EXPECT_EQ(error_of("id: \"a\\nb\"\nrayleigh: {alpha1_per_s: 1, alpha2_s: 1e-7}\nspecific_modulus_m2_s2: 1\namp_scale: 1\n"),
            "m.yaml:1:5: id: must be one line");
  EXPECT_NE(error_of("id: x\nrayleigh: {alpha1_per_s: 1\n").find("m.yaml:"), std::string::npos);
}

TEST(MaterialFile, ReadIsBoundedAndNamesTheFile) {
  test::TempDir dir;
  try {
    read_material_file(dir.file("missing.yaml"));
    FAIL() << "a missing file must be refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing.yaml"), std::string::npos) << e.what();
  }
  try {
    read_material_file("/dev/zero");
    FAIL() << "a device must be refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/dev/zero"), std::string::npos) << e.what();
  }
}
