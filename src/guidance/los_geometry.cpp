// LOS geometry of paper 000 (Yao & Wang 2012): eq. 7, 12, 13–18 on the unit LOS vector.
// See include/evade/guidance/los_geometry.hpp for the frame and the conventions.
#include "evade/guidance/los_geometry.hpp"

#include <cmath>
#include <utility>

namespace evade::guidance {

Vec3 los_unit_from_angles(double elevation_rad, double azimuth_rad) {
  const double ce = std::cos(elevation_rad);
  return Vec3(std::cos(azimuth_rad) * ce, std::sin(azimuth_rad) * ce, std::sin(elevation_rad));
}

// The horizontal part as sqrt(x^2 + y^2), not std::hypot: glibc's hypot is its own
// algorithm per target (an FMA kernel on aarch64), and 257,692 of 2,000,000 arguments came
// out a last bit apart from x86-64's, where sqrt, * and + round the same everywhere
// (docs/GUIDANCE_NODE.md NODE-RT-5). On a unit vector the squares cannot overflow; a
// horizontal part below 1e-154, whose squares underflow, gives the elevation +-pi/2 it has
// to rounding, and the azimuth 0 it is given at the pole.
LosAngles los_angles_from_unit(const Vec3& u_eci) {
  LosAngles a;
  const double horiz = std::sqrt(u_eci.x() * u_eci.x() + u_eci.y() * u_eci.y());
  a.elevation_rad = std::atan2(u_eci.z(), horiz);
  a.azimuth_rad = (horiz > 0.0) ? std::atan2(u_eci.y(), u_eci.x()) : 0.0;
  return a;
}

Vec3 los_unit_rate_from_angle_rates(double elevation_rad, double azimuth_rad,
                                    double elevation_rate_radps, double azimuth_rate_radps) {
  const double ce = std::cos(elevation_rad);
  const double se = std::sin(elevation_rad);
  const double cb = std::cos(azimuth_rad);
  const double sb = std::sin(azimuth_rad);
  const Vec3 y_s(-cb * se, -sb * se, ce);  // eq. 14
  const Vec3 z_s(sb, -cb, 0.0);            // eq. 14
  return elevation_rate_radps * y_s - (azimuth_rate_radps * ce) * z_s;  // eq. 16–18
}

void los_unit_and_rate_from_angles(double elevation_rad, double azimuth_rad,
                                   double elevation_rate_radps, double azimuth_rate_radps,
                                   Vec3* u_eci, Vec3* u_dot_eci_ps) {
  *u_eci = los_unit_from_angles(elevation_rad, azimuth_rad);  // eq. 13
  *u_dot_eci_ps = los_unit_rate_from_angle_rates(elevation_rad, azimuth_rad,
                                                 elevation_rate_radps, azimuth_rate_radps);
}

void los_from_relative(const Vec3& rel_r_eci_m, const Vec3& rel_v_eci_mps, Vec3* u_eci,
                       Vec3* u_dot_eci_ps) {
  const double r = rel_r_eci_m.norm();
  const Vec3 u = rel_r_eci_m / r;
  *u_eci = u;
  *u_dot_eci_ps = (rel_v_eci_mps - u.dot(rel_v_eci_mps) * u) / r;
}

namespace {

// Unit vector of `ref` with its component along u removed; false if ref ∥ u.
bool perpendicular_unit(const Vec3& ref, const Vec3& u, Vec3* out) noexcept {
  const double n_ref = ref.norm();
  if (!(n_ref > 0.0)) return false;
  const Vec3 p = ref / n_ref - u.dot(ref / n_ref) * u;
  const double n = p.norm();
  if (!(n > 1e-6)) return false;
  *out = p / n;
  return true;
}

}  // namespace

bool los_frame(const Vec3& u_eci, const Vec3& u_dot_eci_ps, const Vec3& r_sat_eci_m,
               const Vec3& v_sat_eci_mps, double min_rate_radps, LosFrame* out) noexcept {
  if (!u_eci.allFinite() || !u_dot_eci_ps.allFinite() || !r_sat_eci_m.allFinite() ||
      !v_sat_eci_mps.allFinite() || !std::isfinite(min_rate_radps)) {
    return false;
  }
  const double nu = u_eci.norm();
  const double nr = r_sat_eci_m.norm();
  if (!(nu > 0.0) || !(nr > 0.0)) return false;
  const Vec3 e_r = u_eci / nu;
  const Vec3 zenith = r_sat_eci_m / nr;
  // Keep only the part of u̇ perpendicular to the LOS (the roll about x_s is irrelevant, eq. 16).
  const Vec3 u_dot = u_dot_eci_ps - e_r.dot(u_dot_eci_ps) * e_r;
  const double w = u_dot.norm();  // ω_s, eq. 17
  LosFrame f;
  f.e_r_eci = e_r;
  f.los_rate_radps = w;
  if (w > min_rate_radps && w > 0.0) {
    f.e_theta_eci = u_dot / w;                 // eq. 18
    f.e_omega_eci = e_r.cross(f.e_theta_eci);  // e_ω ∝ r × ṙ (eq. 3)
    if (f.e_omega_eci.dot(zenith) < 0.0) {     // zenith convention
      f.e_omega_eci = -f.e_omega_eci;
      f.e_theta_eci = -f.e_theta_eci;
      f.flipped = true;
    }
  } else {
    // Fallback: e_ω = zenith projected perpendicular to the LOS (velocity if LOS ∥ zenith).
    Vec3 e_w;
    if (!perpendicular_unit(zenith, e_r, &e_w) && !perpendicular_unit(v_sat_eci_mps, e_r, &e_w)) {
      // LOS along both zenith and velocity (impossible for an orbit): any perpendicular.
      const Vec3 ref = (std::abs(e_r.x()) < 0.9) ? Vec3::UnitX() : Vec3::UnitY();
      perpendicular_unit(ref, e_r, &e_w);
    }
    f.e_omega_eci = e_w;
    f.e_theta_eci = e_w.cross(e_r);
    f.fallback = true;
  }
  *out = std::move(f);
  return true;
}

bool zero_effort_miss_m(double range_m, double range_rate_mps, double los_rate_radps,
                        double* zem_m) noexcept {
  if (!(range_rate_mps < 0.0) || !std::isfinite(range_m) || !std::isfinite(los_rate_radps)) {
    return false;
  }
  *zem_m = range_m * range_m * std::abs(los_rate_radps) / std::abs(range_rate_mps);  // eq. 7
  return true;
}

bool time_to_go_s(double range_m, double range_rate_mps, double* tgo_s) noexcept {
  if (!(range_rate_mps < 0.0) || !std::isfinite(range_m)) return false;
  *tgo_s = range_m / std::abs(range_rate_mps);  // eq. 12
  return true;
}

}  // namespace evade::guidance
