// Proven per-arc bounds for the robust screener under two-body and two-body + J2 gravity
// (issue 13). Sources: J2 acceleration, Vallado, Fundamentals of Astrodynamics, 4th ed.,
// eq. 8-30; interpolation and Taylor remainders, e.g. Atkinson, An Introduction to
// Numerical Analysis, 2nd ed., thm. 3.2 and eq. 1.1.6. The constants 3, 42 and 40 and the
// arc lemma are derived in docs/VALIDATION.md ("Robust mode under J2: the no-miss bound").
#include "evade/conjunction/arc_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace evade::conjunction {
namespace {

// J = J2 (Re/r)^2 for the J2 model, 0 for two-body.
double j2_ratio(double r_m, GravityModel model, const EarthModel& earth) {
  if (model != GravityModel::kTwoBodyJ2) return 0.0;
  const double q = earth.re_m / r_m;
  return earth.j2 * q * q;
}

// Distance from the origin to the segment p -> q.
double segment_distance_m(const Vec3& p, const Vec3& q) {
  const Vec3 d = q - p;
  const double dd = d.squaredNorm();
  const double s = dd > 0.0 ? std::clamp(-p.dot(d) / dd, 0.0, 1.0) : 0.0;
  return (p + s * d).norm();
}

}  // namespace

double gravity_bound_mps2(double r_m, GravityModel model, const EarthModel& earth) {
  return earth.mu_m3ps2 / (r_m * r_m) * (1.0 + 3.0 * j2_ratio(r_m, model, earth));
}

double gravity_gradient_bound_ps2(double r_m, GravityModel model, const EarthModel& earth) {
  return 2.0 * earth.mu_m3ps2 / (r_m * r_m * r_m) * (1.0 + 42.0 * j2_ratio(r_m, model, earth));
}

double gravity_hessian_bound(double r_m, GravityModel model, const EarthModel& earth) {
  const double r2 = r_m * r_m;
  return 24.0 * earth.mu_m3ps2 / (r2 * r2) * (1.0 + 40.0 * j2_ratio(r_m, model, earth));
}

ArcBounds arc_bounds(const StateEci& a, const StateEci& b, double h_s, GravityModel model,
                     const EarthModel& earth, double perturbation_mps2, double velocity_error_mps,
                     double position_error_m) {
  // |r''| <= G(r) + perturbation at radius >= r.
  auto g_bound = [&](double r_m) { return gravity_bound_mps2(r_m, model, earth) + perturbation_mps2; };
  // Lemma, first part: the tangent segment keeps the arc above rho_star. With a velocity
  // known to within dv, r(t_a + s) departs from r_a + v_a s by at most dv s + G s^2 / 2.
  // Positions within position_error_m of the exact ones move the segment by at most that.
  const double d_tan = segment_distance_m(a.r_eci_m, a.r_eci_m + h_s * a.v_eci_mps) - position_error_m;
  const double rho0 = 0.5 * d_tan;
  const double rho_star = d_tan - velocity_error_mps * h_s - g_bound(rho0) * h_s * h_s / 2.0;
  if (!(rho_star > rho0)) {
    throw std::runtime_error("arc_bounds: grid step " + std::to_string(h_s) +
                             " s too long for the arc bound (tangent distance " +
                             std::to_string(d_tan) + " m)");
  }
  // Second part: |r''| <= G(rho_star), so the arc stays within G h^2/8 of its chord.
  const double chord_dev = g_bound(rho_star) * h_s * h_s / 8.0;
  ArcBounds out;
  out.r_lo_m = std::max(rho_star, segment_distance_m(a.r_eci_m, b.r_eci_m) - chord_dev - position_error_m);
  out.r_hi_m = std::max(a.r_eci_m.norm(), b.r_eci_m.norm()) + chord_dev + position_error_m;
  out.g_max_mps2 = g_bound(out.r_lo_m);
  out.perturbation_mps2 = perturbation_mps2;
  // |v(t)| <= min(|v_a| + g (t - t_a), |v_b| + g (t_b - t)) <= (|v_a| + |v_b| + g h) / 2,
  // plus dv for velocities known to within dv.
  out.v_max_mps = 0.5 * (a.v_eci_mps.norm() + b.v_eci_mps.norm() + out.g_max_mps2 * h_s) +
                  velocity_error_mps;
  return out;
}

}  // namespace evade::conjunction
