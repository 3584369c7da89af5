// Internal (not installed): fmod(x, 2 pi) for the SGP4 sources, the same double faster.
//
// fmod's result is exact (x - n 2 pi, n = trunc(x / 2 pi), is representable), so one fused
// multiply-add of that n rounds it to itself. q = trunc(x / 2 pi) is n or, where x / 2 pi
// rounds across an integer, n +- 1; then x - q 2 pi has the wrong sign or reaches 2 pi, which
// survives its rounding (rounding keeps the sign, and 2 pi is a double), and one more FMA
// with the corrected q gives the exact remainder. A zero remainder takes the sign of x, as
// fmod's does. Outside |x| < 2^40 (q exact; far beyond any angle SGP4 forms) and for NaN or
// infinity, std::fmod itself. test/sgp4/fmod_two_pi_test.cpp compares the two bit for bit.
#pragma once

#include <cmath>

namespace evade::sgp4::detail {

inline double fmod_two_pi(double x) noexcept {
  constexpr double kTwoPi = 2.0 * 3.14159265358979323846;  // angles.hpp's kTwoPi
  if (!(std::fabs(x) < 0x1p40)) return std::fmod(x, kTwoPi);
  double q = std::trunc(x / kTwoPi);
  double r = std::fma(-q, kTwoPi, x);
  const bool positive = x >= 0.0;
  if (positive ? r < 0.0 : r > 0.0) q += positive ? -1.0 : 1.0;       // q was n + 1 (n - 1)
  else if (positive ? r >= kTwoPi : r <= -kTwoPi) q += positive ? 1.0 : -1.0;  // q was n - 1
  else return r == 0.0 ? std::copysign(0.0, x) : r;
  r = std::fma(-q, kTwoPi, x);
  return r == 0.0 ? std::copysign(0.0, x) : r;
}

}  // namespace evade::sgp4::detail
