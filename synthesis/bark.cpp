#include "synthesis/bark.hpp"

#include <cmath>

namespace ms {

double bark_zwicker_terhardt(double freq_hz) {
  const double r = freq_hz / 7500.0;
  return 13.0 * std::atan(0.00076 * freq_hz) + 3.5 * std::atan(r * r);
}

double bark_wang_sekey_gersho(double freq_hz) { return 6.0 * std::asinh(freq_hz / 600.0); }

}  // namespace ms
