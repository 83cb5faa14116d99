// Reading where an audit's gap lies: the worst Bark bands, the worst frame, and the strike-averaged
// residual map the report draws. The audit computes GapLocation (audit.hpp); these rank and average it.
#pragma once
#include <cstddef>
#include <vector>

#include "analysis/audit/audit.hpp"

namespace ms::audit {

// Up to k band indices, largest band gap first.
std::vector<std::size_t> worst_bands(const GapLocation& location, std::size_t k);

// The frame with the largest gap over strikes and bands (0 when there are none).
std::size_t worst_frame(const GapLocation& location);

// Mean signed difference (model - measured, dB) over strikes, per [band][frame]; NaN where no strike
// has a value there. All maps share one grid.
std::vector<std::vector<double>> mean_gap_map(const std::vector<GapMap>& maps);

}  // namespace ms::audit
