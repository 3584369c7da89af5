// The inverse complementary error function (include/evade/core/erfc_inverse.hpp).
#include "evade/core/erfc_inverse.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "evade/core/constants.hpp"

namespace evade {

double erfc_inverse(double y) {
  if (!(y > 0.0 && y < 2.0))
    throw std::invalid_argument("erfc_inverse: y = " + std::to_string(y) + " outside (0, 2)");
  double x = y < 0.5 ? std::sqrt(-std::log(y)) : 0.0;
  for (int i = 0; i < 100; ++i) {  // converges in a few steps; the bound keeps the loop finite
    const double ec = std::erfc(x);
    const double step =
        (std::log(ec) - std::log(y)) * ec / (-2.0 / std::sqrt(kPi) * std::exp(-x * x));
    x -= step;
    if (std::abs(step) < 1e-14 * (1.0 + std::abs(x))) break;
  }
  return x;
}

}  // namespace evade
