// Drift coefficients of a near-circular orbit under J2 per metre of semi-major-axis change.
//
// Paper 003 (Duan et al., "Collision avoidance of formation-flying satellites under multiple
// configuration constraints"): the relative RAAN drift coefficient K_Omega (the paper's
// "relative RAAN change-rate coefficient"), the relative phase drift coefficient K_phi and
// the along-track coefficient K_am. The paper's equations were lost in extraction; this is
// our derivation, from the J2 secular rates of the mean elements (Vallado 4th ed.
// eq. 9-41, 9-42 and the mean-motion correction; evade::j2_secular_rates):
//
//   n     = sqrt(mu / a^3),   p = a (1 - e^2),   k = J2 (Re / p)^2,   s = sin i
//   Ω̇     = -(3/2) n k cos i                                              (paper eq. 1)
//   u̇     = ω̇ + Ṁ = n + (3/4) n k [(4 - 5 s^2) + sqrt(1-e^2) (2 - 3 s^2)]
//
// At fixed e and i, n ∝ a^(-3/2) and n k ∝ a^(-7/2), so every J2 term scales as a^(-7/2):
//
//   K_Ω  = ∂Ω̇/∂a = -(7/2) Ω̇ / a = (21/4) n J2 Re^2 cos i / (a^3 (1-e^2)^2)      (paper eq. 2)
//   K_φ  = ∂u̇/∂a = -(3/2) n / a  -  (7/2) (u̇ - n) / a                           (paper eq. 4)
//   K_am = a K_φ   [m of along-track drift per m of Δa per day]                   (paper K_am)
//
// A change Δa held for T days moves the RAAN by K_Ω Δa T, the argument of latitude by
// K_φ Δa T and the along-track position by K_am Δa T (paper eqs. 3, 5 and the in-plane
// bound). Units here: rad per metre per day (and m per m per day); the paper quotes K_Ω in
// degrees and radians ("K_Ω(rad) = 2.0953e-8"). Signs are kept: for i < 90 deg, K_Ω > 0
// (a higher orbit regresses more slowly) and K_φ < 0 (a higher orbit falls behind).
#pragma once

#include "evade/core/constants.hpp"

namespace evade::formation {

struct DriftCoefficients {
  double k_omega_rad_per_m_day = 0.0;  ///< ∂Ω̇/∂a [rad / (m day)]
  double k_phi_rad_per_m_day = 0.0;    ///< ∂u̇/∂a, Keplerian + J2 [rad / (m day)]
  double k_phi_kepler_rad_per_m_day = 0.0;  ///< the Keplerian part -3n/(2a) alone
  double k_am_m_per_m_day = 0.0;       ///< a K_φ [m / (m day)]
};

/// Coefficients at (a_m, e, i_rad). Throws std::invalid_argument naming the argument for a
/// non-finite input, a_m <= earth.re_m, e outside [0, 1) or i_rad outside [0, pi].
DriftCoefficients drift_coefficients(double a_m, double e, double i_rad,
                                     const EarthModel& earth = kEarthDefault);

}  // namespace evade::formation
