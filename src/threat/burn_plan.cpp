// make_burn_plan (burn_plan.hpp): the evasive burn at t0 as a one-impulse BurnPlan.
#include "evade/threat/burn_plan.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace evade::threat {

BurnPlan make_burn_plan(const EvasionResult& evasion, std::int64_t plan_id) {
  const Vec3& dv = evasion.dv_rsw_mps;
  if (!dv.allFinite() || !std::isfinite(evasion.dv_mps))
    throw std::invalid_argument("threat-area plan: EvasionResult.dv_rsw_mps is not finite");
  if (!(evasion.dv_mps > 0.0))
    throw std::invalid_argument("threat-area plan: EvasionResult.dv_mps = " +
                                std::to_string(evasion.dv_mps) + ": V_E = 0 is no burn to fly");
  if (std::abs(dv.norm() - evasion.dv_mps) > 1e-9 * evasion.dv_mps)
    throw std::invalid_argument("threat-area plan: |EvasionResult.dv_rsw_mps| = " +
                                std::to_string(dv.norm()) + " differs from dv_mps = " +
                                std::to_string(evasion.dv_mps));
  BurnPlan p;
  p.plan_id = plan_id;
  p.source = static_cast<int>(PlanSource::kThreatArea);
  p.n_impulses = 1;
  p.impulses[0].t_s = 0.0;  // paper 001: the evasive burn at t0
  p.impulses[0].dv_rsw_mps = dv;
  p.impulses[0].dv_eci_valid = false;
  return p;
}

}  // namespace evade::threat
