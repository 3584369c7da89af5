// The 2D assessment of one encounter at TCA in flight form
// (include/evade/assessment/encounter_2d.hpp gives the steps and their sources). The
// arithmetic of each step is the ground's, operation for operation, so that the node and
// evade assess give the same bits (test Encounter2d.*).
#include "evade/assessment/encounter_2d.hpp"
#include "evade/assessment/symmetric_eigen.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

#include "evade/core/elements.hpp"
#include "evade/core/erfc_inverse.hpp"

namespace evade::assessment {
namespace {

// The repaired matrix as a value, as the ground's repair returned it before the flight form
// (the product evaluated into the returned matrix: the same bits as before, test
// golden.OutputsByteIdentical).
// The decomposition the repair uses: Eigen's for the 3x3 (its closed-form tridiagonalization:
// bounded stack), the cyclic Jacobi of symmetric_eigen.hpp for the 6x6 (Eigen's generic
// tridiagonalization takes an alloca GCC cannot bound: scripts/stack_check).
bool decompose(const Mat3& s, Vec3* l, Mat3* v) noexcept {
  const Eigen::SelfAdjointEigenSolver<Mat3> es(s);
  *l = es.eigenvalues();
  *v = es.eigenvectors();
  return true;
}
bool decompose(const Mat6& s, Vec6* l, Mat6* v) noexcept { return symmetric_eigen_jacobi<6>(s, l, v); }

template <class M>
M repaired(const M& c, bool* npd, double* min_eig, CovarianceStatus* st) noexcept {
  *st = CovarianceStatus::kOk;
  if (!c.allFinite()) {
    *st = CovarianceStatus::kNotFinite;
    return M::Zero();
  }
  const double scale = std::max(c.cwiseAbs().maxCoeff(), 1e-300);
  if ((c - c.transpose()).cwiseAbs().maxCoeff() > 1e-9 * scale) {
    *st = CovarianceStatus::kAsymmetric;
    return M::Zero();
  }
  M s = 0.5 * (c + c.transpose());
  Eigen::Matrix<double, M::RowsAtCompileTime, 1> l;
  M vecs;
  if (!decompose(s, &l, &vecs)) {
    *st = CovarianceStatus::kNotConverged;
    return M::Zero();
  }
  *min_eig = l.minCoeff();
  const double floor = std::max(1e-10 * l.maxCoeff(), 1e-12);
  *npd = *min_eig <= 0.0;
  if (!*npd) return s;
  if (l.maxCoeff() <= 0.0) {
    *st = CovarianceStatus::kNoPositiveEigenvalue;
    return M::Zero();
  }
  auto clipped = l;
  for (int i = 0; i < clipped.size(); ++i) clipped(i) = std::max(clipped(i), floor);
  return vecs * clipped.asDiagonal() * vecs.transpose();
}

template <class M>
CovarianceStatus repair_into(const M& c, M* out, bool* npd, double* min_eig) noexcept {
  CovarianceStatus st = CovarianceStatus::kOk;
  *out = repaired(c, npd, min_eig, &st);
  return st;
}

double min_eigenvalue(const Mat3& p) noexcept {
  return Eigen::SelfAdjointEigenSolver<Mat3>(0.5 * (p + p.transpose())).eigenvalues().minCoeff();
}

std::uint16_t failed_bits(const Encounter2d& e, const Encounter2dConfig& cfg) noexcept {
  std::uint16_t b = 0;
  if (e.usage.extended > cfg.pc2d_extended_cutoff) b |= kUsageExtended;
  if (e.usage.offset > cfg.pc2d_offset_cutoff) b |= kUsageOffset;
  if (e.usage.npd) b |= kUsageNpd;
  if (!e.short_term.valid) b |= kUsageShortTerm;
  return b;
}

}  // namespace

CovarianceStatus repair_covariance_into(const Mat3& c, Mat3* out, bool* npd,
                                        double* min_eig) noexcept {
  return repair_into(c, out, npd, min_eig);
}

CovarianceStatus repair_covariance_into(const Mat6& c, Mat6* out, bool* npd,
                                        double* min_eig) noexcept {
  return repair_into(c, out, npd, min_eig);
}

bool encounter_plane_into(const StateEci& obj1, const Mat3& cov1_eci_m2, const StateEci& obj2,
                          const Mat3& cov2_eci_m2, EncounterPlane* out) noexcept {
  const Vec3 r = obj2.r_eci_m - obj1.r_eci_m;
  const Vec3 v = obj2.v_eci_mps - obj1.v_eci_mps;
  EncounterPlane& ep = *out;
  ep = EncounterPlane{};
  ep.rel_speed_mps = v.norm();
  ep.miss_3d_m = r.norm();
  if (!(ep.rel_speed_mps > 0.0)) return false;
  const Vec3 y = v / ep.rel_speed_mps;
  Vec3 x = r - r.dot(y) * y;  // the miss, normal to the relative velocity
  if (x.norm() < 1e-12 * std::max(1.0, r.norm())) {
    x = y.unitOrthogonal();
  } else {
    x.normalize();
  }
  const Vec3 z = x.cross(y);
  ep.axes_eci.row(0) = x.transpose();
  ep.axes_eci.row(1) = y.transpose();
  ep.axes_eci.row(2) = z.transpose();
  ep.tca_offset_check = ep.miss_3d_m > 0.0 ? r.dot(v) / (ep.miss_3d_m * ep.rel_speed_mps) : 0.0;
  ep.miss_m = Vec2(r.dot(x), r.dot(z));
  Eigen::Matrix<double, 2, 3> p;
  p.row(0) = x.transpose();
  p.row(1) = z.transpose();
  ep.cov_m2 = p * (cov1_eci_m2 + cov2_eci_m2) * p.transpose();
  return true;
}

bool principal_axes_into(const EncounterPlane& ep, PrincipalEncounter* out) noexcept {
  Vec2 l;  // ascending
  Mat2 q;
  symmetric_eigen_2x2(ep.cov_m2, &l, &q);  // closed form (symmetric_eigen.hpp): bounded stack
  if (!(l(0) > 0.0)) return false;
  const Vec2 m = q.transpose() * ep.miss_m;
  *out = {m(0), m(1), std::sqrt(l(0)), std::sqrt(l(1))};
  return true;
}

double shorter_period_s(const StateEci& s1, const StateEci& s2, const EarthModel& earth) noexcept {
  return std::min(orbital_period_s(s1, earth.mu_m3ps2), orbital_period_s(s2, earth.mu_m3ps2));
}

ShortTermValues short_term_values(const EncounterPlane& ep, const Mat6& c1, const Mat6& c2,
                                  const StateEci& s1, const StateEci& s2, double hbr_m,
                                  double max_period_fraction, double max_vel_sigma_ratio,
                                  const EarthModel& earth) noexcept {
  ShortTermValues st;
  const Vec3 y = ep.axes_eci.row(1).transpose();
  const Mat3 c = c1.block<3, 3>(0, 0) + c2.block<3, 3>(0, 0);
  const double sigma_along = std::sqrt(std::max(0.0, y.dot(c * y)));
  st.encounter_time_s = 2.0 * (5.0 * sigma_along + hbr_m) / ep.rel_speed_mps;
  st.period_s = shorter_period_s(s1, s2, earth);
  const Mat3 cv = c1.block<3, 3>(3, 3) + c2.block<3, 3>(3, 3);
  st.rel_speed_sigma_mps = std::sqrt(std::max(0.0, y.dot(cv * y)));
  if (st.encounter_time_s > max_period_fraction * st.period_s) {
    st.time_fails = true;
  } else if (st.rel_speed_sigma_mps > max_vel_sigma_ratio * ep.rel_speed_mps) {
    st.speed_fails = true;
  }
  st.valid = !st.time_fails && !st.speed_fails;
  return st;
}

Usage2dValues usage_2d_values(const StateEci& s1, const Mat3& c1_pos, const StateEci& s2,
                              const Mat3& c2_pos, double min_pos_eig1, double min_pos_eig2,
                              double hbr_m, double conj_bound_factor,
                              const EarthModel& earth) noexcept {
  Usage2dValues u;
  const Mat3 c = c1_pos + c2_pos;
  const Eigen::SelfAdjointEigenSolver<Mat3> es(0.5 * (c + c.transpose()));
  Vec3 l = es.eigenvalues();
  const double clip = std::pow(1e-4 * hbr_m, 2);  // CARA's Fclip: eigenvalues below are clipped
  for (int i = 0; i < 3; ++i) l(i) = std::max(l(i), clip);
  const Mat3 ainv = es.eigenvectors() * l.cwiseInverse().asDiagonal() * es.eigenvectors().transpose();
  const Vec3 r = s2.r_eci_m - s1.r_eci_m;
  const Vec3 v = s2.v_eci_mps - s1.v_eci_mps;
  const double vav = v.dot(ainv * v);
  const double period = shorter_period_s(s1, s2, earth);
  if (!(vav > 0.0)) {  // zero relative velocity: the 2D method does not apply at all
    u.zero_speed = true;
    u.extended = u.offset = 1.0;
    return u;
  }
  const double t_min = -r.dot(ainv * v) / vav;
  const double dtau = conj_bound_factor / std::sqrt(vav);
  const double ta = t_min - dtau, tb = t_min + dtau;
  u.extended = std::min(1.0, (tb - ta) / period);
  u.offset = std::min(1.0, std::max(std::abs(ta), std::abs(tb)) / period);
  // CARA's NPDIssues: a position covariance (either object's, or the combined one) with an
  // eigenvalue <= 0. (A zero velocity block, how a CDM says "velocity not known", is not one.)
  u.npd = min_pos_eig1 <= 0.0 || min_pos_eig2 <= 0.0 || es.eigenvalues().minCoeff() <= 0.0;
  return u;
}

const char* encounter_2d_status_name(Encounter2dStatus s) noexcept {
  switch (s) {
    case Encounter2dStatus::kOk: return "ok";
    case Encounter2dStatus::kBadCovariance: return "bad_covariance";
    case Encounter2dStatus::kZeroSpeed: return "zero_relative_speed";
    case Encounter2dStatus::kNotPositive: return "plane_covariance_not_positive";
    case Encounter2dStatus::kBadPc: return "bad_pc_input";
  }
  return "?";
}

Encounter2dStatus assess_encounter_2d(const StateEci& s1, const Mat6& c1, const StateEci& s2,
                                      const Mat6& c2, double hbr_m, const Encounter2dConfig& cfg,
                                      const EarthModel& earth, Pc2dWorkspace* ws,
                                      Encounter2d* out) noexcept {
  Encounter2d& e = *out;
  e = Encounter2d{};
  const Mat6* given[2] = {&c1, &c2};
  double min_pos[2] = {0.0, 0.0};
  for (int i = 0; i < 2; ++i) {
    double min_ev = 0.0;
    bool npd = false;
    if (repair_covariance_into(*given[i], &e.cov_eci[i], &npd, &min_ev) != CovarianceStatus::kOk) {
      return Encounter2dStatus::kBadCovariance;
    }
    e.npd[i] = npd;
    min_pos[i] = min_eigenvalue(given[i]->block<3, 3>(0, 0));
  }
  const Mat3 p1 = e.cov_eci[0].block<3, 3>(0, 0), p2 = e.cov_eci[1].block<3, 3>(0, 0);
  if (!encounter_plane_into(s1, p1, s2, p2, &e.plane)) return Encounter2dStatus::kZeroSpeed;
  if (!principal_axes_into(e.plane, &e.principal)) return Encounter2dStatus::kNotPositive;
  if (pc_2d(e.principal, hbr_m, cfg.pc_rel_tol, ws, &e.pc) != Pc2dStatus::kOk) {
    return Encounter2dStatus::kBadPc;
  }
  e.short_term = short_term_values(e.plane, e.cov_eci[0], e.cov_eci[1], s1, s2, hbr_m,
                                   cfg.short_term_max_period_fraction,
                                   cfg.short_term_max_vel_sigma_ratio, earth);
  e.usage = usage_2d_values(s1, p1, s2, p2, min_pos[0], min_pos[1], hbr_m, cfg.conj_bound_factor,
                            earth);
  e.failed = failed_bits(e, cfg);
  return Encounter2dStatus::kOk;
}

Encounter2dConfig encounter_2d_config(const AssessConfig& c) noexcept {
  Encounter2dConfig f;
  f.pc_rel_tol = c.pc_rel_tol;
  f.short_term_max_period_fraction = c.short_term_max_period_fraction;
  f.short_term_max_vel_sigma_ratio = c.short_term_max_vel_sigma_ratio;
  // A gamma outside erfcinv's domain (the table refuses it) makes the bounds infinite: every
  // extended and offset check fails, the conservative answer.
  const double g = c.conj_duration_gamma;
  f.conj_bound_factor = (g > 0.0 && g < 2.0) ? std::sqrt(2.0) * erfc_inverse(g)
                                             : std::numeric_limits<double>::infinity();
  f.pc2d_extended_cutoff = c.pc2d_extended_cutoff;
  f.pc2d_offset_cutoff = c.pc2d_offset_cutoff;
  return f;
}

}  // namespace evade::assessment
