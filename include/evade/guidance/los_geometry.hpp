// Line-of-sight (LOS) geometry for close-range evasion (paper 000, Yao & Wang 2012, sec. 2–3).
//
// Frame (paper 000 eq. 13, Fig. 1): o_A-x_A y_A z_A is the *translating inertial frame
// centred on the satellite* — its axes are parallel to the ECI (J2000) axes, its origin moves
// with the satellite. Directions are therefore the same in that frame and in ECI, and every
// vector below is written in ECI axes (suffix _eci). Elevation ε is measured from the
// x_A–y_A plane (the ECI equatorial plane) towards +z_A, azimuth β from +x_A towards +y_A:
//   u = x_s = [cos β cos ε, sin β cos ε, sin ε]               (eq. 14)
//   y_s = ∂u/∂ε = [-cos β sin ε, -sin β sin ε, cos ε],  z_s = [sin β, -cos β, 0]
//   u̇ = ε̇ y_s − β̇ cos ε z_s
//   ω_s = |u̇| = sqrt((β̇ cos ε)² + ε̇²)                        (eq. 17)
//   e_θ = u̇ / |u̇| = (ε̇ y_s − β̇ cos ε z_s) / ω_s             (eq. 18)
//   e_ω = e_r × e_θ (∝ r × ṙ),  e_θ = e_ω × e_r               (eq. 3–5)
// We compute on the unit vector u and its rate u̇, never on (ε, β) rates, so nothing is
// singular at ε → ±90° (there β is undefined but u and u̇ are not).
//
// Zenith convention (paper 000 sec. 2, "engineering convention"): if e_ω makes more than 90°
// with the satellite's radial direction (zenith), e_ω and e_θ are both flipped. The evasion
// thrust is then along −e_θ = e_r × e_ω with e_ω·zenith ≥ 0.
//
// Fallback when ω_s is zero or below its noise: e_ω is taken as the component of the zenith
// perpendicular to the LOS (normalised), i.e. the e_ω that the zenith convention prefers
// most; e_θ = e_ω × e_r. Justification: (1) it is memoryless and deterministic; (2) it is a
// fixed point of the law — thrusting along −e_θ_fallback makes the relative velocity grow
// along +e_θ_fallback, so the LOS rate that builds up has exactly this e_ω (positive zenith
// component, no flip) and the direction stays continuous when the true rate takes over.
// If the LOS is within ~1e-6 rad of the zenith the same construction uses the satellite's
// velocity direction instead of the zenith.
//
// Range-dependent quantities (eq. 7 and eq. 12): ZEM = r² ω_s / |ṙ|, t_go = r / |ṙ|; defined
// only while closing (ṙ < 0).
#pragma once

#include "evade/core/state.hpp"

namespace evade::guidance {

/// Unit LOS vector from elevation/azimuth (eq. 14). Frame: ECI-parallel, satellite-centred.
Vec3 los_unit_from_angles(double elevation_rad, double azimuth_rad);

struct LosAngles {
  double elevation_rad = 0.0;  ///< [-π/2, π/2]
  double azimuth_rad = 0.0;    ///< [-π, π]; 0 when the LOS is along ±z (undefined there)
};
/// Inverse of los_unit_from_angles (u need not be exactly unit).
LosAngles los_angles_from_unit(const Vec3& u_eci);

/// u̇ from elevation/azimuth and their rates: u̇ = ε̇ y_s − β̇ cos ε z_s [1/s].
Vec3 los_unit_rate_from_angle_rates(double elevation_rad, double azimuth_rad,
                                    double elevation_rate_radps, double azimuth_rate_radps);
/// Both of the above with one evaluation of the four trigonometric functions.
void los_unit_and_rate_from_angles(double elevation_rad, double azimuth_rad,
                                   double elevation_rate_radps, double azimuth_rate_radps,
                                   Vec3* u_eci, Vec3* u_dot_eci_ps);

/// Unit LOS vector and its time derivative from a relative position/velocity
/// (r = r_target − r_sat): u = r/|r|, u̇ = (ṙ − (u·ṙ) u)/|r|. Precondition: |r| > 0.
void los_from_relative(const Vec3& rel_r_eci_m, const Vec3& rel_v_eci_mps, Vec3* u_eci,
                       Vec3* u_dot_eci_ps);

/// The LOS rotation frame with the zenith convention applied.
struct LosFrame {
  Vec3 e_r_eci = Vec3::UnitX();      ///< unit LOS
  Vec3 e_omega_eci = Vec3::UnitZ();  ///< unit LOS angular-rate axis (after the zenith flip)
  Vec3 e_theta_eci = Vec3::UnitY();  ///< e_ω × e_r (after the zenith flip)
  double los_rate_radps = 0.0;       ///< ω_s = |u̇| (eq. 17), always ≥ 0
  bool flipped = false;              ///< the zenith convention flipped e_ω and e_θ
  bool fallback = false;             ///< ω_s ≤ threshold: the fallback direction was used
};

/// Builds e_r, e_ω, e_θ from u, u̇ and the satellite's position (zenith) and velocity.
/// `min_rate_radps`: at or below it the fallback direction is used (see the file comment).
/// Returns false (and leaves *out unchanged) if an input is not finite or u or r_sat is zero.
bool los_frame(const Vec3& u_eci, const Vec3& u_dot_eci_ps, const Vec3& r_sat_eci_m,
               const Vec3& v_sat_eci_mps, double min_rate_radps, LosFrame* out) noexcept;

/// Zero-effort miss (eq. 7) r² ω_s / |ṙ| [m]; returns false if not closing (ṙ ≥ 0).
bool zero_effort_miss_m(double range_m, double range_rate_mps, double los_rate_radps,
                        double* zem_m) noexcept;
/// Time to go (eq. 12) r / |ṙ| [s]; returns false if not closing (ṙ ≥ 0).
bool time_to_go_s(double range_m, double range_rate_mps, double* tgo_s) noexcept;

}  // namespace evade::guidance
