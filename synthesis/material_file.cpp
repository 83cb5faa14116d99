#include "synthesis/material_file.hpp"

#include <yaml-cpp/yaml.h>

#include "synthesis/bounded_file.hpp"
#include "synthesis/exact_number.hpp"
#include "synthesis/yaml_reader.hpp"

namespace ms {

namespace {

double required(const YamlReader& r, const YAML::Node& map, const std::string& path, const char* key,
                bool strictly_positive) {
  const std::string key_path = path.empty() ? key : path + "." + key;
  if (!map[key]) r.fail(map, path, std::string("missing '") + key + "'");
  return strictly_positive ? r.positive(map[key], key_path) : r.non_negative(map[key], key_path);
}

std::string one_line_text(const YamlReader& r, const YAML::Node& node, const std::string& key_path) {
  const std::string t = r.text(node, key_path);
  if (t.find_first_of("\r\n") != std::string::npos) r.fail(node, key_path, "must be one line");
  return t;
}

DampingLaw read_rayleigh(const YamlReader& r, const YAML::Node& node) {
  r.check_keys(node, "rayleigh", {"alpha1_per_s", "alpha2_s"});
  DampingLaw law{DampingKind::rayleigh, 0.0, 0.0, 1.0, 0.0};
  law.alpha1 = required(r, node, "rayleigh", "alpha1_per_s", false);
  law.alpha2 = required(r, node, "rayleigh", "alpha2_s", false);
  return law;
}

DampingLaw read_hybrid(const YamlReader& r, const YAML::Node& node) {
  r.check_keys(node, "hybrid", {"alpha1_per_s", "alpha2", "alpha3"});
  DampingLaw law{DampingKind::hybrid, 0.0, 0.0, 1.0, 0.0};
  law.alpha1 = required(r, node, "hybrid", "alpha1_per_s", false);
  law.alpha2 = required(r, node, "hybrid", "alpha2", false);
  law.alpha3 = required(r, node, "hybrid", "alpha3", true);
  return law;
}

}  // namespace

Material parse_material_file(const std::string& yaml_text, const std::string& file) {
  const YamlReader r(file);
  const YAML::Node root = r.load(yaml_text);
  if (!root.IsDefined() || root.IsNull()) throw InputError(SourceLocation{file, 1, 1}, "empty material file");
  if (!root.IsMap()) r.fail(root, "", "a material file is a map of keys (id, rayleigh, specific_modulus_m2_s2, amp_scale, ...)");
  r.check_keys(root, "", {"id", "source", "rayleigh", "hybrid", "specific_modulus_m2_s2", "modulus_source",
                          "amp_scale"});
  for (const char* key : {"id", "rayleigh", "specific_modulus_m2_s2", "amp_scale"})
    if (!root[key]) r.fail(root, "", std::string("missing '") + key + "'");
  Material m;
  m.id = one_line_text(r, root["id"], "id");
  if (m.id.empty()) r.fail(root["id"], "id", "must not be empty");
  if (root["source"]) m.source = one_line_text(r, root["source"], "source");
  m.rayleigh = read_rayleigh(r, root["rayleigh"]);
  if (root["hybrid"]) m.hybrid = read_hybrid(r, root["hybrid"]);
  m.specific_modulus_m2_s2 = required(r, root, "", "specific_modulus_m2_s2", true);
  if (root["modulus_source"]) m.modulus_source = one_line_text(r, root["modulus_source"], "modulus_source");
  m.amp_scale = required(r, root, "", "amp_scale", true);
  return m;
}

Material read_material_file(const std::string& path) {
  return parse_material_file(read_bounded_file(path, kYamlFileLimit), path);
}

std::string material_file_yaml(const Material& m) {
  YAML::Emitter out;
  out << YAML::Comment("modalstudy material: c = 2d = alpha1 + alpha2 lambda (rayleigh), lambda = omega^2 [(rad/s)^2]");
  out << YAML::BeginMap;
  out << YAML::Key << "id" << YAML::Value << m.id;
  if (!m.source.empty()) out << YAML::Key << "source" << YAML::Value << m.source;
  out << YAML::Key << "rayleigh" << YAML::Value << YAML::Flow << YAML::BeginMap
      << YAML::Key << "alpha1_per_s" << YAML::Value << exact_number(m.rayleigh.alpha1)
      << YAML::Key << "alpha2_s" << YAML::Value << exact_number(m.rayleigh.alpha2) << YAML::EndMap;
  if (m.hybrid)
    out << YAML::Key << "hybrid" << YAML::Value << YAML::Flow << YAML::BeginMap
        << YAML::Key << "alpha1_per_s" << YAML::Value << exact_number(m.hybrid->alpha1)
        << YAML::Key << "alpha2" << YAML::Value << exact_number(m.hybrid->alpha2)
        << YAML::Key << "alpha3" << YAML::Value << exact_number(m.hybrid->alpha3) << YAML::EndMap;
  out << YAML::Key << "specific_modulus_m2_s2" << YAML::Value << exact_number(m.specific_modulus_m2_s2);
  if (!m.modulus_source.empty()) out << YAML::Key << "modulus_source" << YAML::Value << m.modulus_source;
  out << YAML::Key << "amp_scale" << YAML::Value << exact_number(m.amp_scale);
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

}  // namespace ms
