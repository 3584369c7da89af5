// Hill–Clohessy–Wiltshire state-transition matrix in closed form.
//
// Reference: Clohessy & Wiltshire, J. Aerospace Sci. 27(9), 1960; Vallado 4th ed. eq. 6-66
// (solution of the HCW equations), written in RSW (x radial, y along track,
// z normal). With c = cos nt, s = sin nt:
//   x(t)  = (4-3c) x0 + s/n xd0 + 2(1-c)/n yd0
//   y(t)  = 6(s-nt) x0 + y0 - 2(1-c)/n xd0 + (4s-3nt)/n yd0
//   z(t)  = c z0 + s/n zd0
//   xd(t) = 3ns x0 + c xd0 + 2s yd0
//   yd(t) = -6n(1-c) x0 - 2s xd0 + (4c-3) yd0
//   zd(t) = -ns z0 + c zd0
#include "evade/dynamics/hcw.hpp"

#include <cmath>

namespace evade {

HcwBlocks hcw_stm_blocks(double n_radps, double t_s) {
  const double n = n_radps;
  const double nt = n * t_s;
  const double c = std::cos(nt);
  const double s = std::sin(nt);
  // 1 - cos(nt) written as 2 sin^2(nt/2) to keep relative precision for small nt.
  const double sh = std::sin(0.5 * nt);
  const double omc = 2.0 * sh * sh;
  // s/n and (1-c)/n have finite limits t and n t^2/2 as n -> 0; n > 0 is the normal case.
  const double s_over_n = (n != 0.0) ? s / n : t_s;
  const double omc_over_n = (n != 0.0) ? omc / n : 0.0;
  const double four_s_minus_3nt_over_n = (n != 0.0) ? (4.0 * s - 3.0 * nt) / n : t_s;

  HcwBlocks b;
  b.rr << 4.0 - 3.0 * c, 0.0, 0.0,
          6.0 * (s - nt), 1.0, 0.0,
          0.0, 0.0, c;
  b.rv << s_over_n, 2.0 * omc_over_n, 0.0,
          -2.0 * omc_over_n, four_s_minus_3nt_over_n, 0.0,
          0.0, 0.0, s_over_n;
  b.vr << 3.0 * n * s, 0.0, 0.0,
          -6.0 * n * omc, 0.0, 0.0,
          0.0, 0.0, -n * s;
  b.vv << c, 2.0 * s, 0.0,
          -2.0 * s, 4.0 * c - 3.0, 0.0,
          0.0, 0.0, c;
  return b;
}

Mat6 hcw_stm(double n_radps, double t_s) {
  const HcwBlocks b = hcw_stm_blocks(n_radps, t_s);
  Mat6 phi;
  phi << b.rr, b.rv, b.vr, b.vv;
  return phi;
}

Vec6 hcw_propagate(double n_radps, double t_s, const Vec6& x0_rsw) {
  const HcwBlocks b = hcw_stm_blocks(n_radps, t_s);
  Vec6 x;
  x << b.rr * x0_rsw.head<3>() + b.rv * x0_rsw.tail<3>(),
       b.vr * x0_rsw.head<3>() + b.vv * x0_rsw.tail<3>();
  return x;
}

Eigen::Matrix<double, 6, 3> hcw_impulse_matrix(double n_radps, double t_s) {
  const HcwBlocks b = hcw_stm_blocks(n_radps, t_s);
  Eigen::Matrix<double, 6, 3> m;
  m << b.rv, b.vv;
  return m;
}

Vec6 hcw_impulse_response(double n_radps, double t_s, const Vec3& dv_rsw_mps) {
  const HcwBlocks b = hcw_stm_blocks(n_radps, t_s);
  Vec6 x;
  x << b.rv * dv_rsw_mps, b.vv * dv_rsw_mps;
  return x;
}

Vec6 hcw_derivative(double n_radps, const Vec6& x_rsw) {
  const double n2 = n_radps * n_radps;
  Vec6 dx;
  dx << x_rsw.tail<3>(),
        3.0 * n2 * x_rsw(0) + 2.0 * n_radps * x_rsw(4),  // xddot = 3n^2 x + 2n ydot
        -2.0 * n_radps * x_rsw(3),                       // yddot = -2n xdot
        -n2 * x_rsw(2);                                  // zddot = -n^2 z
  return dx;
}

}  // namespace evade
