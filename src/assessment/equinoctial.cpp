// Equinoctial elements, their Cartesian states and Jacobians
// (include/evade/assessment/equinoctial.hpp gives the sources and the element order).
#include "evade/assessment/equinoctial.hpp"

#include <cmath>

namespace evade::assessment {
namespace {

constexpr double kTwoPi = 6.283185307179586476925;

// The equinoctial frame's unit vectors f, g, w of (chi, psi), prograde form.
struct EqFrame {
  Vec3 f, g, w;
};

EqFrame eq_frame(double chi, double psi) {
  const double c2 = chi * chi;
  const double p2 = psi * psi;
  const double k = 1.0 / (1.0 + c2 + p2);
  EqFrame q;
  q.f = k * Vec3(1.0 - c2 + p2, 2.0 * chi * psi, -2.0 * chi);
  q.g = k * Vec3(2.0 * chi * psi, 1.0 + c2 - p2, 2.0 * psi);
  q.w = k * Vec3(2.0 * chi, -2.0 * psi, 1.0 - c2 - p2);
  return q;
}

// Solves lambda = F + ag cos F - af sin F for the eccentric longitude F (Newton).
double eccentric_longitude(double lambda_rad, double af, double ag) {
  double f = lambda_rad;
  for (int i = 0; i < 60; ++i) {
    const double s = std::sin(f);
    const double c = std::cos(f);
    const double step = (f + ag * c - af * s - lambda_rad) / (1.0 - ag * s - af * c);
    f -= step;
    if (std::abs(step) < 1e-15 * (1.0 + std::abs(f))) break;
  }
  return f;
}

}  // namespace

bool cartesian_to_equinoctial(const Vec6& x, double mu_m3ps2, Vec6* e) {
  const Vec3 r = x.head<3>();
  const Vec3 v = x.tail<3>();
  const double rm = r.norm();
  const double v2 = v.squaredNorm();
  const double a = mu_m3ps2 * rm / (2.0 * mu_m3ps2 - v2 * rm);
  if (!(a > 0.0) || !std::isfinite(a)) return false;
  const Vec3 ecc = ((v2 - mu_m3ps2 / rm) * r - r.dot(v) * v) / mu_m3ps2;
  const Vec3 h = r.cross(v);
  if (!(ecc.squaredNorm() < 1.0) || !(h.norm() > 0.0)) return false;
  const Vec3 w = h / h.norm();
  if (w.z() + 1.0 <= 1e-10) return false;
  const double chi = w.x() / (1.0 + w.z());
  const double psi = -w.y() / (1.0 + w.z());
  const EqFrame q = eq_frame(chi, psi);
  const double af = q.f.dot(ecc);
  const double ag = q.g.dot(ecc);
  const double e2 = af * af + ag * ag;
  if (!(e2 < 1.0)) return false;
  const double big_x = q.f.dot(r);
  const double big_y = q.g.dot(r);
  const double sq = std::sqrt(1.0 - e2);
  const double b = 1.0 / (1.0 + sq);
  const double den = a * sq;
  const double sin_f = ag + ((1.0 - ag * ag * b) * big_y - b * ag * af * big_x) / den;
  const double cos_f = af + ((1.0 - af * af * b) * big_x - b * ag * af * big_y) / den;
  const double f = std::atan2(sin_f, cos_f);
  double lm = std::fmod(f + ag * cos_f - af * sin_f, kTwoPi);
  if (lm < 0.0) lm += kTwoPi;
  *e << std::sqrt(mu_m3ps2 / (a * a * a)), af, ag, chi, psi, lm;
  return true;
}

Vec6 equinoctial_to_cartesian(const Vec6& e, double mu_m3ps2) {
  const double n = e(0), af = e(1), ag = e(2);
  const double a = std::cbrt(mu_m3ps2 / (n * n));
  const double b = 1.0 / (1.0 + std::sqrt(1.0 - af * af - ag * ag));
  const double f = eccentric_longitude(e(5), af, ag);
  const double s = std::sin(f);
  const double c = std::cos(f);
  const double big_x = a * ((1.0 - ag * ag * b) * c + af * ag * b * s - af);
  const double big_y = a * ((1.0 - af * af * b) * s + af * ag * b * c - ag);
  const double rm = a * (1.0 - af * c - ag * s);
  const double k = n * a * a / rm;
  const double xd = k * (af * ag * b * c - (1.0 - ag * ag * b) * s);
  const double yd = k * ((1.0 - af * af * b) * c - af * ag * b * s);
  const EqFrame q = eq_frame(e(3), e(4));
  Vec6 x;
  x << big_x * q.f + big_y * q.g, xd * q.f + yd * q.g;
  return x;
}

Mat6 jacobian_equinoctial_to_cartesian(const Vec6& e, const Vec6& x, double mu_m3ps2) {
  const double n = e(0), af = e(1), ag = e(2), chi = e(3), psi = e(4);
  const Vec3 r = x.head<3>();
  const Vec3 v = x.tail<3>();
  const double rm = r.norm();
  const double r3 = rm * rm * rm;
  const double a3 = mu_m3ps2 / (n * n);
  const double a = std::cbrt(a3);
  const double big_a = n * a * a;
  const double big_b = std::sqrt(1.0 - af * af - ag * ag);
  const double cc = 2.0 / (1.0 + chi * chi + psi * psi);
  const EqFrame q = eq_frame(chi, psi);
  const double px = q.f.dot(r), py = q.g.dot(r), vx = q.f.dot(v), vy = q.g.dot(v);
  const double ab = big_a * big_b, nb1 = n * (big_b + 1.0), ar3 = big_a / r3;
  // Partials of the in-plane coordinates (X, Y) and velocities (Xd, Yd) in af and ag.
  const double dx_daf = ag * vx / nb1 + a * (py * vx / ab - 1.0);
  const double dy_daf = ag * vy / nb1 - a * (px * vx / ab);
  const double dx_dag = -af * vx / nb1 + a * (py * vy / ab);
  const double dy_dag = -af * vy / nb1 - a * (px * vy / ab + 1.0);
  const double dvx_daf = a * vx * vy / ab - ar3 * (a * ag * px / (big_b + 1.0) + px * py / big_b);
  const double dvy_daf = -a * vx * vx / ab - ar3 * (a * ag * py / (big_b + 1.0) - px * px / big_b);
  const double dvx_dag = a * vy * vy / ab + ar3 * (a * af * px / (big_b + 1.0) - py * py / big_b);
  const double dvy_dag = -a * vx * vy / ab + ar3 * (a * af * py / (big_b + 1.0) + px * py / big_b);
  Mat6 j;
  j.col(0) << (-2.0 / (3.0 * n)) * r, (1.0 / (3.0 * n)) * v;
  j.col(1) << dx_daf * q.f + dy_daf * q.g, dvx_daf * q.f + dvy_daf * q.g;
  j.col(2) << dx_dag * q.f + dy_dag * q.g, dvx_dag * q.f + dvy_dag * q.g;
  j.col(3) << cc * (psi * (py * q.f - px * q.g) - px * q.w),
      cc * (psi * (vy * q.f - vx * q.g) - vx * q.w);
  j.col(4) << cc * (chi * (px * q.g - py * q.f) + py * q.w),
      cc * (chi * (vx * q.g - vy * q.f) + vy * q.w);
  j.col(5) << v / n, (-n * a3 / r3) * r;
  return j;
}

Mat6 jacobian_epoch_elements_to_cartesian(const Vec6& e0, double dt_s, double mu_m3ps2,
                                          Vec6* x_out) {
  Vec6 et = e0;
  et(5) = e0(5) + e0(0) * dt_s;
  const Vec6 x = equinoctial_to_cartesian(et, mu_m3ps2);
  if (x_out != nullptr) *x_out = x;
  Mat6 j = jacobian_equinoctial_to_cartesian(et, x, mu_m3ps2);
  j.col(0) += dt_s * j.col(5);  // d lambda_M(t) / d n = dt
  return j;
}

}  // namespace evade::assessment
