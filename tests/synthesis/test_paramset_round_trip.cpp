// Every shipped parameter set (stimuli/** and each protocol's stimulus sets with their overrides) survives read_recipe -> write_yaml -> read_recipe: the written text is a fixed point of
// the writer, and both recipes resolve to the same recipe hash and render the same samples.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>

#include "synthesis/paramset.hpp"
#include "synthesis/paramset_recipe.hpp"
#include "synthesis/stimulus.hpp"

using namespace ms;
namespace fs = std::filesystem;

namespace {

struct ShippedSet {
  fs::path path;
  std::vector<std::string> overrides;
  std::string name;  // for messages
};

std::vector<fs::path> yaml_files(const fs::path& folder) {
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(folder))
    if (e.path().extension() == ".yaml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

// "a.b=value" for every leaf of a protocol stimulus's `set:` / `prune:` map, as a protocol applies them.
void flatten(const YAML::Node& node, const std::string& prefix, std::vector<std::string>& out) {
  if (node.IsMap()) {
    for (auto it = node.begin(); it != node.end(); ++it)
      flatten(it->second, prefix.empty() ? it->first.Scalar() : prefix + "." + it->first.Scalar(), out);
    return;
  }
  YAML::Emitter e;
  e << YAML::Flow << node;
  out.push_back(prefix + "=" + e.c_str());
}

std::vector<ShippedSet> shipped_sets() {
  const fs::path root(MODALSTUDY_SOURCE_DIR);
  std::vector<ShippedSet> sets;
  for (const fs::path& p : yaml_files(root / "stimuli")) sets.push_back({p, {}, p.string()});
  for (const fs::path& protocol : yaml_files(root / "protocols")) {
    const YAML::Node stimuli = YAML::LoadFile(protocol.string())["stimuli"];
    for (auto it = stimuli.begin(); it != stimuli.end(); ++it) {
      const YAML::Node s = it->second;
      if (!s["paramset"]) continue;
      ShippedSet set{protocol.parent_path() / s["paramset"].as<std::string>(), {}, protocol.string() + ": " + it->first.Scalar()};
      if (s["set"]) flatten(s["set"], "", set.overrides);
      if (s["prune"]) flatten(s["prune"], "prune", set.overrides);
      sets.push_back(set);
    }
  }
  return sets;
}

TEST(ParamSetRoundTrip, EveryShippedSetWritesBackToTheSameRecipe) {
  const std::vector<ShippedSet> sets = shipped_sets();
  ASSERT_GE(sets.size(), 40u + 120u);  // stimuli, protocols' stimuli
  std::size_t with_overrides = 0;
  for (const ShippedSet& s : sets) {
    SCOPED_TRACE(s.name);
    const ParamSetRecipe recipe = read_recipe_file(s.path.string(), s.overrides);
    const std::string text = write_yaml(recipe);
    const ParamSetRecipe again = read_recipe(text, "written.yaml", recipe.origin.base_dir);
    EXPECT_EQ(write_yaml(again), text);
    const ParamSet a = resolve(recipe), b = resolve(again);
    ASSERT_EQ(a.recipe_hash, b.recipe_hash) << text;
    EXPECT_EQ(a.model.modes.size(), b.model.modes.size());
    EXPECT_EQ(render_stimulus(a).audio.samples, render_stimulus(b).audio.samples);
    // The written set is the one load_paramset reads.
    EXPECT_EQ(load_paramset(s.path.string(), s.overrides).recipe_hash, a.recipe_hash);
    with_overrides += !s.overrides.empty();
  }
  EXPECT_GE(with_overrides, 120u);
}

}  // namespace
