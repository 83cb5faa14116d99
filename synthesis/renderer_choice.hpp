// How a parameter set's modes become sound: `renderer:` (the resonator bank, or Pd-style band-pass
// filters, bandpass_bank.hpp) with its `bandpass:` section, and `phase:` (each mode's onset).
#pragma once
#include <optional>
#include <vector>

#include "synthesis/bandpass_bank.hpp"
#include "synthesis/name_table.hpp"

namespace ms {

enum class Renderer { resonator, bandpass };
inline constexpr NameTable<Renderer, 2> kRendererNames{
    {{Renderer::resonator, "resonator"}, {Renderer::bandpass, "bandpass"}}};

// sine: every mode starts at 0 (an object at rest struck at t = 0); cosine: at its amplitude, the
// click-like onset of Eq 2.1 in Skandalou & Ireland (2017), y = sum A e^{-d t} cos(2 pi f t).
enum class OnsetPhase { sine, cosine };
inline constexpr NameTable<OnsetPhase, 2> kOnsetPhaseNames{
    {{OnsetPhase::sine, "sine"}, {OnsetPhase::cosine, "cosine"}}};

// `bandpass: {q: 1500 | [q per mode], material: wood, q_table: table_4_1, clip: 1}`: the Q of every
// filter (one number, one per written mode, or a material's from one of the thesis's tables) and the
// clipper's level (0: none).
struct BandpassRecipe {
  std::vector<double> q;
  std::optional<BandpassMaterial> material;
  QTable q_table = QTable::table_4_1;
  double clip = 1.0;
};

// The Q values the section gives: as written, or the material's.
inline std::vector<double> bandpass_q(const BandpassRecipe& b) {
  return b.material ? std::vector<double>{material_q(*b.material, b.q_table)} : b.q;
}

}  // namespace ms
