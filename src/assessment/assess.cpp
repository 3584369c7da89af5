// One-encounter assessment (include/evade/assessment/assess.hpp gives the steps and sources).
#include "evade/assessment/assess.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "evade/assessment/covariance.hpp"
#include "evade/assessment/encounter_2d.hpp"
#include "evade/assessment/covariance_propagation.hpp"
#include "evade/core/elements.hpp"
#include "evade/dynamics/gravity.hpp"

namespace evade::assessment {
namespace {

// Newton on the range rate with two-body + J2 propagation of both objects.
void bring_to_tca(ConjunctionInput& in, const AssessConfig& cfg, Assessment& out) {
  double total = 0.0;
  if (cfg.tca_search_s == 0.0) return;  // states used as given
  for (int it = 0; it < 50; ++it) {
    const Vec3 r = in.obj[1].state.r_eci_m - in.obj[0].state.r_eci_m;
    const Vec3 v = in.obj[1].state.v_eci_mps - in.obj[0].state.v_eci_mps;
    if (!(v.squaredNorm() > 0.0)) return;  // no closest approach to find: the given epoch
    // f = r.v, f' = |v|^2 + r.(a2 - a1): the relative acceleration matters for slow pairs
    // (without it Newton oscillates with a growing step when r.a > |v|^2).
    const Vec3 a_rel =
        orbit_derivative(in.obj[1].state.stacked(), GravityModel::kTwoBodyJ2, in.earth).tail<3>() -
        orbit_derivative(in.obj[0].state.stacked(), GravityModel::kTwoBodyJ2, in.earth).tail<3>();
    const double df = v.squaredNorm() + r.dot(a_rel);
    const double dt = -r.dot(v) / (df > 0.0 ? df : v.squaredNorm());
    if (std::abs(dt) < 1e-6) {
      out.tca_shift_s = total;
      return;
    }
    if (std::abs(total + dt) > cfg.tca_search_s) break;
    for (auto& o : in.obj) {
      if (o.has_velocity_cov) o.cov_eci = propagate_covariance_j2(o.state, o.cov_eci, dt, in.earth);
      o.state = propagate_j2(o.state, dt, in.earth);
    }
    total += dt;
  }
  throw std::invalid_argument("assess: no local TCA within assessment.tca_search_s = " +
                              std::to_string(cfg.tca_search_s) + " s of the given states");
}

// The flight form's figures (encounter_2d.hpp: short_term_values), with the ground's reasons.
ShortTermCheck short_term(const Assessment& a, double hbr_m, const AssessConfig& cfg,
                          const EarthModel& earth) {
  ShortTermCheck st;
  const ShortTermValues v = short_term_values(
      a.plane, a.at_tca[0].cov_eci, a.at_tca[1].cov_eci, a.at_tca[0].state, a.at_tca[1].state,
      hbr_m, cfg.short_term_max_period_fraction, cfg.short_term_max_vel_sigma_ratio, earth);
  st.encounter_time_s = v.encounter_time_s;
  st.period_s = v.period_s;
  st.rel_speed_sigma_mps = v.rel_speed_sigma_mps;
  if (v.time_fails) {
    st.valid = false;
    st.reason = "encounter time " + std::to_string(st.encounter_time_s) + " s exceeds " +
                std::to_string(cfg.short_term_max_period_fraction) + " of the orbital period (" +
                std::to_string(st.period_s) + " s): the relative motion is not rectilinear";
  } else if (v.speed_fails) {
    st.valid = false;
    st.reason = "relative-speed sigma " + std::to_string(st.rel_speed_sigma_mps) +
                " m/s exceeds " + std::to_string(cfg.short_term_max_vel_sigma_ratio) +
                " of the relative speed: velocity uncertainty is not negligible";
  }
  return st;
}

// The covariances at TCA: as given (3D-Nc takes them so) and repaired by eigenvalue clipping
// (the 2D methods and the Monte Carlo), the whole 6x6 when its velocity block is given.
void repair_covariances(const ConjunctionInput& in, Assessment* a) {
  for (int i = 0; i < 2; ++i) {
    a->at_tca[i] = in.obj[i];
    a->cov_unrepaired_eci[i] = in.obj[i].cov_eci;
    const Mat3 p = in.obj[i].cov_eci.block<3, 3>(0, 0);
    a->min_position_eigenvalue_m2[i] =
        Eigen::SelfAdjointEigenSolver<Mat3>(0.5 * (p + p.transpose())).eigenvalues().minCoeff();
    if (in.obj[i].has_velocity_cov) {  // the whole 6x6 (a velocity-block NPD is an NPD too)
      bool npd = false;
      double min_ev = 0.0;
      a->at_tca[i].cov_eci = repair_covariance6(in.obj[i].cov_eci, in.obj[i].name, &npd, &min_ev);
      a->npd[i] = npd;
      a->min_eigenvalue[i] = min_ev;
      continue;
    }
    const CovarianceRepair rep =
        repair_covariance(in.obj[i].cov_eci.block<3, 3>(0, 0), in.obj[i].name);
    a->at_tca[i].cov_eci.block<3, 3>(0, 0) = rep.cov_m2;
    a->npd[i] = rep.npd;
    a->min_eigenvalue[i] = rep.min_eigenvalue_m2;
  }
}

// The encounter plane and the plane methods (pc_methods.hpp); undefined (NaN) when the
// relative speed is zero.
void plane_methods(const ConjunctionInput& in, const AssessConfig& cfg, Assessment* a) {
  const Vec3 v_rel = a->at_tca[1].state.v_eci_mps - a->at_tca[0].state.v_eci_mps;
  if (!(v_rel.squaredNorm() > 0.0)) {  // no encounter plane
    const double nan = std::numeric_limits<double>::quiet_NaN();
    a->plane.miss_3d_m = (a->at_tca[1].state.r_eci_m - a->at_tca[0].state.r_eci_m).norm();
    a->principal = {nan, nan, nan, nan};
    a->plane_pc = undefined_plane_pc_values();
    a->short_term.valid = false;
    a->short_term.reason = "relative speed is zero: no encounter plane, the 2D Pc is undefined";
    return;
  }
  a->plane = encounter_plane(a->at_tca[0].state, a->at_tca[0].cov_eci.block<3, 3>(0, 0),
                             a->at_tca[1].state, a->at_tca[1].cov_eci.block<3, 3>(0, 0));
  a->principal = principal_axes(a->plane);
  a->plane_pc = plane_pc_values(a->principal, in.hbr_m, cfg.pc_rel_tol);
  a->short_term = short_term(*a, in.hbr_m, cfg, in.earth);
}

// The requested Monte Carlo, the last step of an assessment.
void run_requested_mc(const ConjunctionInput& in, const AssessConfig& cfg,
                      const std::optional<MonteCarloOptions>& mc, const McBlockRunner& runner,
                      Assessment* a) {
  if (!mc) return;
  MonteCarloOptions o = *mc;
  if (!(o.window_s > 0.0)) o.window_s = mc_window_s(*a, in.hbr_m, cfg, in.earth);
  a->mc = pc_monte_carlo(mc_encounter(*a, in.hbr_m, in.earth), o, runner);
}

}  // namespace

double shorter_period_s(const Assessment& a, const EarthModel& earth) {
  return shorter_period_s(a.at_tca[0].state, a.at_tca[1].state, earth);
}

McEncounter mc_encounter(const Assessment& a, double hbr_m, const EarthModel& earth) {
  return McEncounter{a.at_tca[0].state, a.at_tca[1].state, a.at_tca[0].cov_eci,
                     a.at_tca[1].cov_eci, hbr_m, earth};
}

double pc_at_tca(const ObjectState& o1, const ObjectState& o2, double hbr_m, double rel_tol) {
  const Mat3 c1 = repair_covariance(o1.cov_eci.block<3, 3>(0, 0), o1.name).cov_m2;
  const Mat3 c2 = repair_covariance(o2.cov_eci.block<3, 3>(0, 0), o2.name).cov_m2;
  const EncounterPlane ep = encounter_plane(o1.state, c1, o2.state, c2);
  return pc_2d(principal_axes(ep), hbr_m, rel_tol).pc;
}

double mc_window_s(const Assessment& a, double hbr_m, const AssessConfig& cfg,
                   const EarthModel& earth) {
  Eigen::SelfAdjointEigenSolver<Mat3> es(a.at_tca[0].cov_eci.block<3, 3>(0, 0) +
                                         a.at_tca[1].cov_eci.block<3, 3>(0, 0));
  const double sigma_max = std::sqrt(std::max(0.0, es.eigenvalues().maxCoeff()));
  const double w = (cfg.mc_window_sigmas * sigma_max + hbr_m) / a.plane.rel_speed_mps;
  return std::min(w, 0.5 * shorter_period_s(a, earth));
}

Assessment assess(const ConjunctionInput& given, const AssessConfig& cfg,
                  const std::optional<MonteCarloOptions>& mc, const McBlockRunner& runner) {
  if (!(given.hbr_m > 0.0) || !std::isfinite(given.hbr_m)) {
    throw std::invalid_argument("assess: hbr_m must be a finite number > 0 m");
  }
  ConjunctionInput in = given;
  Assessment a;
  bring_to_tca(in, cfg, a);
  a.tca_method = cfg.tca_search_s == 0.0 ? "states used as given (assessment.tca_search_s = 0)"
                 : a.tca_shift_s == 0.0
                     ? "states given at TCA (r.v = 0 to 1 us)"
                     : "both states propagated (two-body + J2, DOP853) to the local TCA, "
                       "Newton on the range rate";
  const bool both6 = in.obj[0].has_velocity_cov && in.obj[1].has_velocity_cov;
  a.covariance_propagation =
      a.tca_shift_s == 0.0 ? "none (covariances given at TCA)"
      : both6 ? "Phi P Phi^T with the two-body + J2 state transition matrix"
              : "6x6 covariances by the J2 state transition matrix; 3x3 position covariances "
                "held constant over the shift";
  repair_covariances(in, &a);
  plane_methods(in, cfg, &a);
  run_requested_mc(in, cfg, mc, runner, &a);
  return a;
}

}  // namespace evade::assessment
