// pi and 2 pi for the SGP4 sources (one declaration for every file of the library), and the
// reference's fmod(x, 2 pi) as the same double computed faster (fmod_two_pi.hpp).
#pragma once

#include "evade/sgp4/internal/fmod_two_pi.hpp"

namespace evade::sgp4::detail {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kTwoPi = 2.0 * kPi;

}  // namespace evade::sgp4::detail
