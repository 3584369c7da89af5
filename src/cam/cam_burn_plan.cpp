// make_cam_burn_plan (include/evade/cam/cam_burn_plan.hpp).
#include "evade/cam/cam_burn_plan.hpp"

#include "evade/core/epoch.hpp"

#include <cmath>
#include <stdexcept>

namespace evade::cam {

BurnPlan make_cam_burn_plan(const CamPlan& plan, std::int64_t plan_id) {
  if (!plan.maneuver_needed)
    throw std::invalid_argument("CamPlan: no burn to publish (Pc and miss already meet the request)");
  if (!plan.dv_rtn_mps.allFinite() || !plan.dv_eci_mps.allFinite())
    throw std::invalid_argument("CamPlan.dv_rtn_mps / dv_eci_mps is not finite");
  BurnPlan p;
  p.plan_id = plan_id;
  p.n_impulses = 1;
  p.impulses[0].t_s = 0.0;
  p.impulses[0].dv_rsw_mps = plan.dv_rtn_mps;
  p.impulses[0].dv_eci_valid = true;
  p.impulses[0].dv_eci_mps = plan.dv_eci_mps;
  p.source = static_cast<int>(PlanSource::kCollisionAvoidance);
  return p;
}

std::int64_t unix_utime_from_j2000(double t_j2000_s) {
  const double us = std::round((t_j2000_s + kJ2000UnixS) * 1e6);
  if (!std::isfinite(us) || us < 0.0 || us > 9.2e18)
    throw std::invalid_argument("epoch outside the Unix time range of a utime");
  return static_cast<std::int64_t>(us);
}

}  // namespace evade::cam
