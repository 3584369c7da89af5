// Two-body + J2 propagation with the state transition matrix (include/evade/autonomy/orbit_stm.hpp).
#include "evade/autonomy/orbit_stm.hpp"

#include <cmath>
#include <utility>

namespace evade::autonomy {
namespace {

constexpr double kMinRadiusM = 1.0e5;  // below: not an orbit (and 1/r^9 would overflow first)

// A state the equations of motion hold for: finite, outside the minimum radius.
bool physical(const Vec6& x) noexcept { return x.allFinite() && x.head<3>().norm() >= kMinRadiusM; }

Vec6 derivative(const Vec6& x, const EarthModel& earth) noexcept {
  Vec6 d;
  d.head<3>() = x.tail<3>();
  d.tail<3>() = gravity_j2_eci_mps2(x.head<3>(), earth);
  return d;
}

// d/dt Phi = A Phi with A = [[0, I], [G, 0]]: the top rows are Phi's bottom rows, the bottom
// rows G times Phi's top rows.
Mat6 phi_derivative(const Vec6& x, const Mat6& phi, const EarthModel& earth) noexcept {
  Mat6 d;
  d.topRows<3>() = phi.bottomRows<3>();
  d.bottomRows<3>() = gravity_j2_gradient(x.head<3>(), earth) * phi.topRows<3>();
  return d;
}

}  // namespace

Vec3 gravity_j2_eci_mps2(const Vec3& r, const EarthModel& earth) noexcept {
  const double r2 = r.squaredNorm();
  const double rn = std::sqrt(r2);
  const Vec3 two_body = (-earth.mu_m3ps2 / (r2 * rn)) * r;  // Vallado eq. 1-14
  const double z2 = r.z() * r.z() / r2;
  // Vallado eq. 8-30: a_J2 = k / r^5 [x(1 - 5 z^2/r^2), y(1 - 5 z^2/r^2), z(3 - 5 z^2/r^2)].
  const double k = -1.5 * earth.j2 * earth.mu_m3ps2 * earth.re_m * earth.re_m / (r2 * r2 * rn);
  const double xy = 1.0 - 5.0 * z2;
  return two_body + Vec3(k * r.x() * xy, k * r.y() * xy, k * r.z() * (3.0 - 5.0 * z2));
}

// G = mu / r^3 (3 r_hat r_hat^T - I) for two-body; for J2 (a = k f, k = -3/2 J2 mu Re^2):
//   df_x/dx = r^-5 - 5 (x^2 + z^2) r^-7 + 35 x^2 z^2 r^-9,  df_x/dy = -5 x y r^-7 + 35 x y z^2 r^-9,
//   df_x/dz = -15 x z r^-7 + 35 x z^3 r^-9,   df_y/dy = r^-5 - 5 (y^2 + z^2) r^-7 + 35 y^2 z^2 r^-9,
//   df_y/dz = -15 y z r^-7 + 35 y z^3 r^-9,   df_z/dz = 3 r^-5 - 30 z^2 r^-7 + 35 z^4 r^-9.
Mat3 gravity_j2_gradient(const Vec3& r, const EarthModel& earth) noexcept {
  const double x = r.x(), y = r.y(), z = r.z();
  const double r2 = r.squaredNorm();
  const double rn = std::sqrt(r2);
  const double r5 = 1.0 / (r2 * r2 * rn);
  const double r7 = r5 / r2;
  const double r9 = r7 / r2;
  Mat3 g = (earth.mu_m3ps2 * r5) * (3.0 * r * r.transpose() - r2 * Mat3::Identity());
  const double k = -1.5 * earth.j2 * earth.mu_m3ps2 * earth.re_m * earth.re_m;
  const double z2 = z * z;
  Mat3 j;
  j(0, 0) = r5 - 5.0 * (x * x + z2) * r7 + 35.0 * x * x * z2 * r9;
  j(1, 1) = r5 - 5.0 * (y * y + z2) * r7 + 35.0 * y * y * z2 * r9;
  j(2, 2) = 3.0 * r5 - 30.0 * z2 * r7 + 35.0 * z2 * z2 * r9;
  j(0, 1) = j(1, 0) = -5.0 * x * y * r7 + 35.0 * x * y * z2 * r9;
  j(0, 2) = j(2, 0) = -15.0 * x * z * r7 + 35.0 * x * z * z2 * r9;
  j(1, 2) = j(2, 1) = -15.0 * y * z * r7 + 35.0 * y * z * z2 * r9;
  g += k * j;
  return g;
}

Vec6 rk4_step(const Vec6& x, double h, const EarthModel& earth) noexcept {
  const Vec6 k1 = derivative(x, earth);
  const Vec6 k2 = derivative(x + 0.5 * h * k1, earth);
  const Vec6 k3 = derivative(x + 0.5 * h * k2, earth);
  const Vec6 k4 = derivative(x + h * k3, earth);
  return x + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

StateStm rk4_step_stm(const StateStm& s, double h, const EarthModel& earth) noexcept {
  const Vec6 k1 = derivative(s.x_eci, earth);
  const Mat6 p1 = phi_derivative(s.x_eci, s.phi, earth);
  const Vec6 xa = s.x_eci + 0.5 * h * k1;
  const Vec6 k2 = derivative(xa, earth);
  const Mat6 p2 = phi_derivative(xa, s.phi + 0.5 * h * p1, earth);
  const Vec6 xb = s.x_eci + 0.5 * h * k2;
  const Vec6 k3 = derivative(xb, earth);
  const Mat6 p3 = phi_derivative(xb, s.phi + 0.5 * h * p2, earth);
  const Vec6 xc = s.x_eci + h * k3;
  const Vec6 k4 = derivative(xc, earth);
  const Mat6 p4 = phi_derivative(xc, s.phi + h * p3, earth);
  StateStm out;
  out.x_eci = s.x_eci + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  out.phi = s.phi + (h / 6.0) * (p1 + 2.0 * p2 + 2.0 * p3 + p4);
  return out;
}

std::int64_t steps_for(double dt_s, double h_max_s) noexcept {
  if (!(h_max_s > 0.0) || !std::isfinite(dt_s) || dt_s == 0.0) return 0;
  const double n = std::ceil(std::fabs(dt_s) / h_max_s);
  if (!(n < static_cast<double>(kMaxSteps))) return kMaxSteps;
  return n < 1.0 ? 1 : static_cast<std::int64_t>(n);
}

bool propagate_stm(StateStm* s, double dt_s, double h_max_s, const EarthModel& earth) noexcept {
  const std::int64_t n = steps_for(dt_s, h_max_s);
  if (!physical(s->x_eci) || !(h_max_s > 0.0) || !std::isfinite(dt_s)) return false;
  if (n == 0) return true;
  const double h = dt_s / static_cast<double>(n);
  StateStm t = *s;
  for (std::int64_t i = 0; i < n; ++i) {
    t = rk4_step_stm(t, h, earth);
    if (!physical(t.x_eci)) return false;
  }
  *s = std::move(t);
  return true;
}

bool propagate(Vec6* x, double dt_s, double h_max_s, const EarthModel& earth) noexcept {
  const std::int64_t n = steps_for(dt_s, h_max_s);
  if (!physical(*x) || !(h_max_s > 0.0) || !std::isfinite(dt_s)) return false;
  if (n == 0) return true;
  const double h = dt_s / static_cast<double>(n);
  Vec6 t = *x;
  for (std::int64_t i = 0; i < n; ++i) {
    t = rk4_step(t, h, earth);
    if (!physical(t)) return false;
  }
  *x = t;
  return true;
}

}  // namespace evade::autonomy
