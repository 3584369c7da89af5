// The inverse complementary error function: x with erfc(x) = y, for 0 < y < 2 (Newton on
// log erfc from the asymptotic start sqrt(-ln y), which keeps full relative accuracy down to
// y = 1e-300). Used for conjunction-duration bounds sqrt(2) erfc^-1(gamma) sigma (Coppola
// 2012; NASA CARA's usage checks).
#pragma once

namespace evade {

/// Throws std::invalid_argument for y outside (0, 2) or NaN.
double erfc_inverse(double y);

}  // namespace evade
