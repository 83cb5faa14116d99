#include "synthesis/material.hpp"

namespace ms {

namespace {

constexpr const char* kRen =
    "Ren, Yeh, Lin (2013), Example-guided physically based modal sound synthesis, ACM TOG 32(1); "
    "Ren (2014) thesis Table 3.1 {alpha, beta, gamma, sigma}";
constexpr const char* kRenGamma =
    "Ren 2013 gamma, fitted on Ren's meshes; used here as E/rho in m^2/s^2";
constexpr const char* kSterling =
    "Sterling, Rewkowski, Klatzky, Lin (2019), Audio-material reconstruction for virtualized "
    "reality using a probabilistic damping model, IEEE TVCG; Table 1.1 (lambda = omega^2, c = 2d)";
constexpr const char* kHandbook = "typical handbook E/rho (not from the paper)";

Material ren(const char* name, double alpha, double beta, double gamma, double sigma) {
  Material m;
  m.id = std::string("ren2013/") + name;
  m.source = kRen;
  m.rayleigh = {DampingKind::rayleigh, alpha, beta, 1.0, 0.0};
  m.specific_modulus_m2_s2 = gamma;
  m.modulus_source = kRenGamma;
  m.amp_scale = sigma;
  return m;
}

Material sterling(const char* name, double a1, double a2, double h1, double h2, double h3,
                  double e_over_rho) {
  Material m;
  m.id = std::string("sterling2019/") + name;
  m.source = kSterling;
  m.rayleigh = {DampingKind::rayleigh, a1, a2, 1.0, 0.0};
  m.hybrid = DampingLaw{DampingKind::hybrid, h1, h2, h3, 0.0};
  m.specific_modulus_m2_s2 = e_over_rho;
  m.modulus_source = kHandbook;
  return m;
}

std::vector<Material> build_library() {
  return {
      ren("wood", 2.1364, 3.0828e-6, 6.6625e5, 3.3276e-6),
      ren("plastic", 52.627, 8.7753e-7, 8.9008e4, 2.2050e-6),
      ren("metal", 6.3035, 2.1160e-8, 4.5935e5, 9.2624e-6),
      ren("glass", 18.301, 1.4342e-7, 2.0282e5, 1.1336e-6),
      ren("porcelain", 0.037388, 8.4142e-8, 3.7068e5, 4.3800e-7),
      // E/rho: porcelain 70 GPa / 2400; travertine 35 GPa / 2500; wood (along grain) 11 GPa / 600;
      // steel 200 GPa / 7850; ABS plastic 2.3 GPa / 1050; soda-lime glass 70 GPa / 2500.
      sterling("porcelain", 3.9, 1e-8, 3.9, 5.2e-9, 1.027, 2.9e7),
      sterling("travertine", 1.3, 2.5e-8, 1.3, 2.5e-8, 1.001, 1.4e7),
      sterling("wood", 39.0, 1.3e-7, 39.0, 2.1e-7, 0.978, 1.8e7),
      sterling("steel", 2.3, 6.9e-8, 2.4, 5.5e-8, 1.011, 2.55e7),
      sterling("plastic", 39.8, 1.3e-7, 34.83, 4.1e-7, 0.95, 2.2e6),
      sterling("glass", 2.0, 7.8e-8, 1.9, 1.5e-7, 0.974, 2.8e7),
  };
}

}  // namespace

const std::vector<Material>& material_library() {
  static const std::vector<Material> library = build_library();
  return library;
}

const Material* find_material(const std::string& id) {
  for (const auto& m : material_library())
    if (m.id == id) return &m;
  return nullptr;
}

std::vector<std::string> material_ids() {
  std::vector<std::string> ids;
  for (const auto& m : material_library()) ids.push_back(m.id);
  return ids;
}

}  // namespace ms
