// Flight-grade orbit propagation with its state transition matrix, two-body + J2, for the
// onboard conjunction response (docs/AUTONOMY.md AUT-3, AUT-4). The equations of motion are
// those of evade::dynamics (Vallado, "Fundamentals of Astrodynamics and Applications", 4th ed.,
// eq. 1-14 two-body and eq. 8-30 J2); the variational equations dPhi/dt = A(r) Phi with
// A = [[0, I], [G(r), 0]], G = da/dr (Montenbruck & Gill, "Satellite Orbits", 2000, sec. 7.2),
// the J2 part of G written out from eq. 8-30 (j2_gradient, checked against central differences
// of the acceleration by test). Classical RK4 (Hairer, Norsett & Wanner, "Solving Ordinary
// Differential Equations I", Table 1.2) with a fixed step: the number of steps of a propagation
// is known before it starts (bounded loops), nothing allocates or throws.
#pragma once

#include <cstdint>

#include "evade/core/constants.hpp"
#include "evade/core/state.hpp"

namespace evade::autonomy {

/// A state and its transition matrix from some epoch: Phi = d x(t) / d x(t0).
struct StateStm {
  Vec6 x_eci = Vec6::Zero();      ///< [r; v] ECI [m, m/s]
  Mat6 phi = Mat6::Identity();    ///< d x / d x0 [-, s, 1/s]
};

/// Two-body + J2 acceleration [m/s^2].
Vec3 gravity_j2_eci_mps2(const Vec3& r_eci_m, const EarthModel& earth) noexcept;
/// Its gradient da/dr [1/s^2], two-body + J2 (symmetric).
Mat3 gravity_j2_gradient(const Vec3& r_eci_m, const EarthModel& earth) noexcept;

/// One RK4 step of h_s (either sign) of the state and its transition matrix.
StateStm rk4_step_stm(const StateStm& s, double h_s, const EarthModel& earth) noexcept;
/// One RK4 step of the state alone.
Vec6 rk4_step(const Vec6& x_eci, double h_s, const EarthModel& earth) noexcept;

/// The number of equal steps no longer than h_max_s covering |dt_s| (at least 1, at most
/// kMaxSteps; 0 for dt_s = 0).
inline constexpr std::int64_t kMaxSteps = 1000000;
std::int64_t steps_for(double dt_s, double h_max_s) noexcept;

/// Propagates s by dt_s in steps_for(dt_s, h_max_s) equal steps. False (s unchanged) when the
/// input is not finite, h_max_s <= 0 or the state leaves the physical range (|r| < 1e5 m).
bool propagate_stm(StateStm* s, double dt_s, double h_max_s, const EarthModel& earth) noexcept;
bool propagate(Vec6* x_eci, double dt_s, double h_max_s, const EarthModel& earth) noexcept;

}  // namespace evade::autonomy
