// modalstudy materials [--json]: the material library with each entry's source.
#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>

#include "studyapp/cli/commands.hpp"
#include "synthesis/material.hpp"

namespace ms::cli {

namespace {
nlohmann::json law_json(const DampingLaw& law) {
  return {{"law", to_string(law.kind)}, {"alpha1", law.alpha1}, {"alpha2", law.alpha2}, {"alpha3", law.alpha3}};
}
}  // namespace

void register_materials(CLI::App& app) {
  auto json = std::make_shared<bool>(false);
  CLI::App* cmd = app.add_subcommand("materials", "List the material library (damping laws, E/rho, sources)");
  cmd->add_flag("--json", *json, "Print one JSON object");
  cmd->callback([json] {
    if (*json) {
      nlohmann::json j = {{"materials", nlohmann::json::array()}};
      for (const Material& m : material_library()) {
        nlohmann::json e = {{"id", m.id},
                            {"source", m.source},
                            {"rayleigh", law_json(m.rayleigh)},
                            {"specific_modulus_m2_s2", m.specific_modulus_m2_s2},
                            {"modulus_source", m.modulus_source},
                            {"amp_scale", m.amp_scale}};
        if (m.hybrid) e["hybrid"] = law_json(*m.hybrid);
        j["materials"].push_back(e);
      }
      std::cout << j.dump() << "\n";
      return;
    }
    std::printf("%-24s %10s %11s %10s %11s %7s %11s\n", "id", "alpha1", "alpha2", "hyb.a1", "hyb.a2",
                "hyb.a3", "E/rho");
    for (const Material& m : material_library()) {
      if (m.hybrid)
        std::printf("%-24s %10.5g %11.5g %10.5g %11.5g %7.4g %11.5g\n", m.id.c_str(), m.rayleigh.alpha1,
                    m.rayleigh.alpha2, m.hybrid->alpha1, m.hybrid->alpha2, m.hybrid->alpha3,
                    m.specific_modulus_m2_s2);
      else
        std::printf("%-24s %10.5g %11.5g %10s %11s %7s %11.5g\n", m.id.c_str(), m.rayleigh.alpha1,
                    m.rayleigh.alpha2, "-", "-", "-", m.specific_modulus_m2_s2);
    }
    std::printf("\nlambda = omega^2 [(rad/s)^2], c = 2d = alpha1 + alpha2 lambda (Rayleigh), "
                "alpha1 + alpha2 omega^(2 alpha3) (hybrid)\n");
    for (const Material& m : material_library())
      if (m.id.rfind("ren", 0) == 0 || m.id == "sterling2019/porcelain")
        std::printf("%s: %s\n", m.id.substr(0, m.id.find('/')).c_str(), m.source.c_str());
  });
}

}  // namespace ms::cli
