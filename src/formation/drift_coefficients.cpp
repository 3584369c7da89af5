// Drift coefficients K_Ω, K_φ, K_am (paper 003 eqs. 2, 4 and the in-plane bound); the
// derivation is in include/evade/formation/drift_coefficients.hpp.
#include "evade/formation/drift_coefficients.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "evade/dynamics/gravity.hpp"

namespace evade::formation {

DriftCoefficients drift_coefficients(double a_m, double e, double i_rad, const EarthModel& earth) {
  auto bad = [](const std::string& what, double v, const char* range) {
    throw std::invalid_argument("drift_coefficients: " + what + " = " + std::to_string(v) +
                                " outside " + range);
  };
  if (!std::isfinite(a_m) || !(a_m > earth.re_m)) bad("a_m", a_m, "(re_m, inf)");
  if (!std::isfinite(e) || !(e >= 0.0 && e < 1.0)) bad("e", e, "[0, 1)");
  if (!std::isfinite(i_rad) || !(i_rad >= 0.0 && i_rad <= kPi)) bad("i_rad", i_rad, "[0, pi]");
  const J2SecularRates r = j2_secular_rates(a_m, e, i_rad, earth);
  const double n = std::sqrt(earth.mu_m3ps2 / (a_m * a_m * a_m));
  DriftCoefficients k;
  k.k_omega_rad_per_m_day = -3.5 * r.raan_dot_radps / a_m * kSecondsPerDay;  // eq. 2
  k.k_phi_kepler_rad_per_m_day = -1.5 * n / a_m * kSecondsPerDay;
  k.k_phi_rad_per_m_day =
      k.k_phi_kepler_rad_per_m_day - 3.5 * (r.arg_latitude_dot_radps - n) / a_m * kSecondsPerDay;
  k.k_am_m_per_m_day = a_m * k.k_phi_rad_per_m_day;
  return k;
}

}  // namespace evade::formation
