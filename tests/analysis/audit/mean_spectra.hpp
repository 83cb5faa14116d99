// The mean of several drawn renderings' Bark spectra, cell by cell: what a closed-form expected power
// (a room's, a noise tail's) is compared with in the tests.
#pragma once
#include <cstddef>

#include "analysis/audit/audit_model.hpp"

namespace ms::audit {

// draw(k) for k = 0 .. draws - 1 returns one rendering's spectra.
template <class Draw>
Spectra mean_spectra(int draws, Draw draw) {
  Spectra mean{};
  for (int k = 0; k < draws; ++k) {
    const Spectra one = draw(k);
    for (std::size_t r = 0; r < kResolutions; ++r) {
      if (k == 0) mean[r] = one[r];
      else
        for (std::size_t c = 0; c < one[r].power.size(); ++c) mean[r].power[c] += one[r].power[c];
    }
  }
  for (BarkSpectrogram& b : mean)
    for (double& p : b.power) p /= draws;
  return mean;
}

}  // namespace ms::audit
