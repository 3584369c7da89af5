// TEME -> J2000: Vallado, Crawford, Hujsak & Kelso (2006), AIAA 2006-6753, sec. on TEME and
// its conversion (teme2eci): r_eci = P N R3(-Eq_eq) r_teme, Eq_eq = dpsi cos(eps_mean).
// Precession: IAU-1976 (Lieske et al. 1977) zeta, theta, z in arcsec, r_mod = R3(-z) R2(theta)
// R3(-zeta) r_j2000. Nutation: IAU-1980 (Seidelmann 1982), Delaunay arguments of the 1980
// theory, the 10 largest terms of the 106-term series (amplitudes in 0.1 mas), mean
// obliquity eps = 84381.448" - 46.8150" T - 0.00059" T^2 + 0.001813" T^3;
// r_tod = R1(-eps - deps) R3(-dpsi) R1(eps) r_mod. Rotations are frame (passive) rotations.
#include "evade/sgp4/teme_to_j2000.hpp"

#include "angles.hpp"

#include <cmath>

namespace evade::sgp4 {
namespace {

using detail::kPi;
constexpr double kArcsec = kPi / (180.0 * 3600.0);
constexpr double kDeg = kPi / 180.0;

Eigen::Matrix3d rot1(double a) {
  const double c = std::cos(a), s = std::sin(a);
  Eigen::Matrix3d m;
  m << 1, 0, 0, 0, c, s, 0, -s, c;
  return m;
}
Eigen::Matrix3d rot2(double a) {
  const double c = std::cos(a), s = std::sin(a);
  Eigen::Matrix3d m;
  m << c, 0, -s, 0, 1, 0, s, 0, c;
  return m;
}
Eigen::Matrix3d rot3(double a) {
  const double c = std::cos(a), s = std::sin(a);
  Eigen::Matrix3d m;
  m << c, s, 0, -s, c, 0, 0, 0, 1;
  return m;
}

// One term: multipliers of (l, l', F, D, Omega); dpsi = (a + b T) sin(arg),
// deps = (c + d T) cos(arg), in 0.1 mas.
struct NutationTerm {
  int l, lp, f, d, om;
  double a, b, c, dd;
};

constexpr NutationTerm kTerms[] = {
    {0, 0, 0, 0, 1, -171996.0, -174.2, 92025.0, 8.9}, {0, 0, 2, -2, 2, -13187.0, -1.6, 5736.0, -3.1},
    {0, 0, 2, 0, 2, -2274.0, -0.2, 977.0, -0.5},      {0, 0, 0, 0, 2, 2062.0, 0.2, -895.0, 0.5},
    {0, 1, 0, 0, 0, 1426.0, -3.4, 54.0, -0.1},        {1, 0, 0, 0, 0, 712.0, 0.1, -7.0, 0.0},
    {0, 1, 2, -2, 2, -517.0, 1.2, 224.0, -0.6},       {0, 0, 2, 0, 1, -386.0, -0.4, 200.0, 0.0},
    {1, 0, 2, 0, 2, -301.0, 0.0, 129.0, -0.1},        {0, -1, 2, -2, 2, 217.0, -0.5, -95.0, 0.3},
};

}  // namespace

Nutation nutation_iau80(double t) noexcept {
  // Delaunay arguments of the 1980 theory (degrees + arcsec rates).
  const double l = ((0.064 * t + 31.310) * t + 1717915922.6330) * t / 3600.0 + 134.96298139;
  const double lp = ((-0.012 * t - 0.577) * t + 129596581.2240) * t / 3600.0 + 357.52772333;
  const double f = ((0.011 * t - 13.257) * t + 1739527263.1370) * t / 3600.0 + 93.27191028;
  const double d = ((0.019 * t - 6.891) * t + 1602961601.3280) * t / 3600.0 + 297.85036306;
  const double om = ((0.008 * t + 7.455) * t - 6962890.5390) * t / 3600.0 + 125.04452222;
  Nutation n;
  for (const NutationTerm& k : kTerms) {
    const double arg = std::fmod(k.l * l + k.lp * lp + k.f * f + k.d * d + k.om * om, 360.0) * kDeg;
    n.dpsi_rad += (k.a + k.b * t) * std::sin(arg);
    n.deps_rad += (k.c + k.dd * t) * std::cos(arg);
  }
  n.dpsi_rad *= 1e-4 * kArcsec;
  n.deps_rad *= 1e-4 * kArcsec;
  n.eps_mean_rad = (84381.448 - 46.8150 * t - 0.00059 * t * t + 0.001813 * t * t * t) * kArcsec;
  return n;
}

Eigen::Matrix3d teme_to_j2000_matrix(double t_utc_s) noexcept {
  const double t = t_utc_s / (86400.0 * 36525.0);
  const double t2 = t * t, t3 = t2 * t;
  const double zeta = (2306.2181 * t + 0.30188 * t2 + 0.017998 * t3) * kArcsec;
  const double theta = (2004.3109 * t - 0.42665 * t2 - 0.041833 * t3) * kArcsec;
  const double z = (2306.2181 * t + 1.09468 * t2 + 0.018203 * t3) * kArcsec;
  const Eigen::Matrix3d p_j2000_to_mod = rot3(-z) * rot2(theta) * rot3(-zeta);
  const Nutation n = nutation_iau80(t);
  const Eigen::Matrix3d n_mod_to_tod = rot1(-(n.eps_mean_rad + n.deps_rad)) * rot3(-n.dpsi_rad) * rot1(n.eps_mean_rad);
  const double eq_eq = n.dpsi_rad * std::cos(n.eps_mean_rad);
  const Eigen::Matrix3d tod_from_teme = rot3(-eq_eq);
  return p_j2000_to_mod.transpose() * n_mod_to_tod.transpose() * tod_from_teme;
}

void teme_to_j2000(double t_utc_s, const Eigen::Vector3d& r_teme_m, const Eigen::Vector3d& v_teme_mps,
                   Eigen::Vector3d& r_j2000_m, Eigen::Vector3d& v_j2000_mps) noexcept {
  const Eigen::Matrix3d m = teme_to_j2000_matrix(t_utc_s);
  r_j2000_m = m * r_teme_m;
  v_j2000_mps = m * v_teme_mps;
}

}  // namespace evade::sgp4
