#include "synthesis/threshold_in_quiet.hpp"

#include <cmath>

namespace ms {

double threshold_in_quiet_db_spl(double freq_hz) {
  const double khz = freq_hz / 1000.0;
  const double dip = khz - 3.3;
  return 3.64 * std::pow(khz, -0.8) - 6.5 * std::exp(-0.6 * dip * dip) + 1e-3 * (khz * khz) * (khz * khz);
}

}  // namespace ms
