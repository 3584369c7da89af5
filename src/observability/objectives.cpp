// Paper 004 objectives: eq. 23 (the vector-product objective, maximized; eq. 24 is its
// negative) and the direct change of the measured angles of eq. 3. See objectives.hpp.
#include "evade/observability/objectives.hpp"

#include <cmath>

namespace evade::observability {

double paper_objective(const SampledProblem& s, double eps_rad, double theta_rad) {
  const Vec3 dv = dv_paper_from_angles(eps_rad, theta_rad, s.problem.dv_mps);
  double f = 0.0;
  for (std::size_t k = 0; k < s.t_s.size(); ++k) {
    const Vec3 a_o = -s.r_chaser_p[k];  // A_kO: chaser -> nominal evader
    const Vec3 o_a = s.b_r_p[k] * dv;   // OA'_k = B_r(t_k, t0) u_E
    const double on = o_a.norm();
    if (on > 0.0) {
      f += a_o.dot(o_a) / (a_o.norm() * on);
    } else if (s.problem.k0 == K0Term::kLimit) {
      // t_k = t0 (or a zero of B_r): OA'(t) ≈ (t - t0) Δv, so unit(OA') -> unit(Δv).
      f += a_o.dot(dv) / (a_o.norm() * dv.norm());
    }
  }
  return f;
}

LosChange los_change_dv(const SampledProblem& s, const Vec3& dv_p_mps) {
  LosChange out;
  for (std::size_t k = 0; k < s.t_s.size(); ++k) {
    const Vec3 r_nominal = -s.r_chaser_p[k];                 // evader rel. chaser, no burn
    const Vec3 r_burn = r_nominal + s.b_r_p[k] * dv_p_mps;   // evader rel. chaser, burn
    const auto a0 = los_angles(r_nominal);
    const auto a1 = los_angles(r_burn);
    const double de = pitch_difference(a1.first, a0.first);
    const double dt = a1.second - a0.second;  // arctan(y / sqrt(x²+z²)) is continuous
    out.sum_rad += std::hypot(de, dt);
    out.sum_abs_azimuth_rad += std::abs(dt);
    out.sum_abs_elevation_rad += std::abs(de);
    out.max_azimuth_change_rad = std::max(out.max_azimuth_change_rad, std::abs(dt));
    out.max_elevation_change_rad = std::max(out.max_elevation_change_rad, std::abs(de));
  }
  return out;
}

LosChange los_change(const SampledProblem& s, double eps_rad, double theta_rad) {
  return los_change_dv(s, dv_paper_from_angles(eps_rad, theta_rad, s.problem.dv_mps));
}

}  // namespace evade::observability
