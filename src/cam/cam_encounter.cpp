// A burn's outcome by propagation and its linear model (include/evade/cam/cam_encounter.hpp
// gives the method and the sources).
#include "evade/cam/cam_encounter.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "evade/assessment/covariance_propagation.hpp"
#include "evade/assessment/pc_method_choice.hpp"
#include "evade/core/frames.hpp"

namespace evade::cam {

struct CamEncounter::Burned {
  StateEci primary, secondary;  ///< at the new TCA
  double t_s = 0.0;             ///< new TCA minus the unburned TCA
  Mat6 phi = Mat6::Identity();  ///< primary: d x(new TCA) / d x(burn, after the burn)
  Mat3 cov1 = Mat3::Zero(), cov2 = Mat3::Zero();
  Mat6 cov1_full = Mat6::Zero(), cov2_full = Mat6::Zero();  ///< velocity block zero if unknown
};

namespace {

assessment::ObjectState object(const char* name, const StateEci& s, const Mat3& cov) {
  assessment::ObjectState o;
  o.name = name;
  o.state = s;
  o.cov_eci.block<3, 3>(0, 0) = cov;
  return o;
}

EncounterOutcome make_outcome(const StateEci& s1, const Mat3& c1, const StateEci& s2,
                              const Mat3& c2, double t_s, double hbr_m, double rel_tol) {
  EncounterOutcome e;
  e.tca_s = t_s;
  e.miss_m = (s2.r_eci_m - s1.r_eci_m).norm();
  e.rel_speed_mps = (s2.v_eci_mps - s1.v_eci_mps).norm();
  e.pc = assessment::pc_at_tca(object("primary", s1, c1), object("secondary", s2, c2), hbr_m, rel_tol);
  return e;
}

}  // namespace

EncounterOutcome CamLinearModel::predict(const Vec3& dv_rtn_mps) const {
  const Vec3 d = dv_rtn_mps - dv_ref_rtn_mps;
  StateEci s1{primary_ref.r_eci_m + dr_ddv * d, primary_ref.v_eci_mps + dv_ddv * d};
  StateEci s2 = secondary_ref;
  const Vec3 r = s2.r_eci_m - s1.r_eci_m, v = s2.v_eci_mps - s1.v_eci_mps;
  const double dt = -r.dot(v) / v.squaredNorm();  // rectilinear shift to the closest approach
  s1.r_eci_m += s1.v_eci_mps * dt;
  s2.r_eci_m += s2.v_eci_mps * dt;
  return make_outcome(s1, cov1_m2, s2, cov2_m2, t_ref_s + dt, hbr_m, pc_rel_tol);
}

CamEncounter::CamEncounter(const assessment::ConjunctionInput& in, double lead_s, const assessment::AssessConfig& cfg)
    : cfg_(cfg), earth_(in.earth), lead_s_(lead_s), hbr_m_(in.hbr_m) {
  if (!std::isfinite(lead_s) || !(lead_s > 0.0))
    throw std::invalid_argument("lead_s = " + std::to_string(lead_s) +
                                ": the burn must come a finite time > 0 s before TCA");
  a_ = assessment::assess(in, cfg);
  if (!(a_.plane.rel_speed_mps > 0.0))
    throw std::invalid_argument("plan cam: the relative speed is zero: the planner's 2D Pc model "
                                "is undefined (evade assess gives the 3D-Nc Pc)");
  for (int i = 0; i < 2; ++i) six_[i] = in.obj[i].has_velocity_cov;
  burn_state_ = assessment::propagate_j2(a_.at_tca[0].state, -lead_s, earth_);
  cov1_burn_ = six_[0] ? assessment::propagate_covariance_j2(a_.at_tca[0].state, a_.at_tca[0].cov_eci,
                                                 -lead_s, earth_)
                       : a_.at_tca[0].cov_eci;
  rtn_to_eci_ = rotation_eci_to_rsw(burn_state_).transpose();
}

CamEncounter::Burned CamEncounter::propagate_burn(const Vec3& dv_rtn_mps) const {
  StateEci s = burn_state_;
  s.v_eci_mps += rtn_to_eci_ * dv_rtn_mps;
  Burned b;
  b.primary = assessment::propagate_j2(s, lead_s_, earth_);
  b.secondary = a_.at_tca[1].state;
  bool converged = false;
  for (int it = 0; it < 50 && !converged; ++it) {  // Newton on the range rate
    const Vec3 r = b.secondary.r_eci_m - b.primary.r_eci_m;
    const Vec3 v = b.secondary.v_eci_mps - b.primary.v_eci_mps;
    const double dt = -r.dot(v) / v.squaredNorm();
    converged = std::abs(dt) < 1e-6;
    if (converged) break;
    if (!(std::abs(b.t_s + dt) <= cfg_.tca_search_s))
      throw std::invalid_argument(
          "after the burn no local TCA within assessment.tca_search_s = " +
          std::to_string(cfg_.tca_search_s) + " s of the first TCA");
    b.primary = assessment::propagate_j2(b.primary, dt, earth_);
    b.secondary = assessment::propagate_j2(b.secondary, dt, earth_);
    b.t_s += dt;
  }
  if (!converged) throw std::invalid_argument("after the burn the TCA iteration did not converge");
  b.cov1_full = a_.at_tca[0].cov_eci;
  b.cov2_full = a_.at_tca[1].cov_eci;
  b.phi = assessment::state_transition_j2(s, lead_s_ + b.t_s, earth_);
  if (six_[0]) {
    const Mat6 c = b.phi * cov1_burn_ * b.phi.transpose();
    b.cov1_full = 0.5 * (c + c.transpose());  // symmetric to rounding
  }
  if (six_[1])
    b.cov2_full = assessment::propagate_covariance_j2(a_.at_tca[1].state, a_.at_tca[1].cov_eci, b.t_s, earth_);
  b.cov1 = b.cov1_full.block<3, 3>(0, 0);
  b.cov2 = b.cov2_full.block<3, 3>(0, 0);
  return b;
}

EncounterOutcome CamEncounter::outcome(const Vec3& dv_rtn_mps) const {
  const Burned b = propagate_burn(dv_rtn_mps);
  return make_outcome(b.primary, b.cov1, b.secondary, b.cov2, b.t_s, hbr_m_, cfg_.pc_rel_tol);
}

CamLinearModel CamEncounter::linearize(const Vec3& dv_rtn_mps, EncounterOutcome* at_ref) const {
  const Burned b = propagate_burn(dv_rtn_mps);
  CamLinearModel m;
  m.dv_ref_rtn_mps = dv_rtn_mps;
  m.t_ref_s = b.t_s;
  m.primary_ref = b.primary;
  m.secondary_ref = b.secondary;
  m.cov1_m2 = b.cov1;
  m.cov2_m2 = b.cov2;
  m.dr_ddv = b.phi.block<3, 3>(0, 3) * rtn_to_eci_;
  m.dv_ddv = b.phi.block<3, 3>(3, 3) * rtn_to_eci_;
  m.hbr_m = hbr_m_;
  m.pc_rel_tol = cfg_.pc_rel_tol;
  if (at_ref)
    *at_ref = make_outcome(b.primary, b.cov1, b.secondary, b.cov2, b.t_s, hbr_m_, cfg_.pc_rel_tol);
  return m;
}

namespace {

RecommendedPc recommended(const assessment::Assessment& a, double hbr_m, const assessment::AssessConfig& cfg,
                          const EarthModel& earth, bool six_by_six) {
  const assessment::PcChoice c = assessment::choose_pc(a, hbr_m, cfg, earth, six_by_six);
  return {c.pc, c.method, c.why};
}

}  // namespace

RecommendedPc CamEncounter::recommended_pc_before() const {
  return recommended(a_, hbr_m_, cfg_, earth_, six_[0] && six_[1]);
}

RecommendedPc CamEncounter::recommended_pc(const Vec3& dv_rtn_mps) const {
  const Burned b = propagate_burn(dv_rtn_mps);
  assessment::ConjunctionInput in;
  in.hbr_m = hbr_m_;
  in.earth = earth_;
  in.obj[0] = a_.at_tca[0];
  in.obj[1] = a_.at_tca[1];
  in.obj[0].state = b.primary;
  in.obj[1].state = b.secondary;
  in.obj[0].cov_eci = b.cov1_full;
  in.obj[1].cov_eci = b.cov2_full;
  assessment::AssessConfig cfg = cfg_;
  cfg.tca_search_s = 0.0;  // the states are at the refined new TCA
  return recommended(assessment::assess(in, cfg), hbr_m_, cfg, earth_, six_[0] && six_[1]);
}

}  // namespace evade::cam
