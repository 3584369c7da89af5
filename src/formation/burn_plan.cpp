// make_burn_plan (burn_plan.hpp): the decision's tangential burns as BurnPlan impulses, with
// the states at the burns from the verifier's propagation.
#include "evade/formation/burn_plan.hpp"

#include <stdexcept>
#include <string>
#include <vector>

#include "evade/core/frames.hpp"
#include "evade/formation/burn_propagation.hpp"

namespace evade::formation {

BurnPlan make_burn_plan(const FormationSpec& spec, const SatelliteId& threatened,
                        const Decision& decision, const PropagationSettings& settings,
                        std::int64_t plan_id) {
  if (!decision.maneuver_needed)
    throw std::invalid_argument("formation plan: no maneuver needed (Decision.maneuver_needed "
                                "= false): nothing to publish");
  if (!decision.feasible)
    throw std::invalid_argument("formation plan: the decision is not feasible (" +
                                decision.summary + "): its trade-off is not published");
  const std::vector<TangentialBurn> burns = decision.burn_plan();
  if (burns.empty() || burns.size() > static_cast<std::size_t>(BurnPlan::kMaxImpulses))
    throw std::invalid_argument("formation plan: " + std::to_string(burns.size()) +
                                " burns, expected 1.." + std::to_string(BurnPlan::kMaxImpulses));
  std::vector<double> t_s;
  t_s.reserve(burns.size());
  for (const TangentialBurn& b : burns) t_s.push_back(b.t_s);
  std::vector<AppliedBurn> applied;
  const StateEci s0 = state_from_mean_elements(spec.sat(threatened), spec.earth);
  const std::vector<StateEci> at =
      propagate_with_burns(s0, t_s, burns, spec.earth, settings.integrator, &applied);
  BurnPlan p;
  p.plan_id = plan_id;
  p.source = static_cast<int>(PlanSource::kFormation);
  p.n_impulses = static_cast<int>(burns.size());
  for (std::size_t k = 0; k < burns.size(); ++k) {
    ImpulsiveBurn& imp = p.impulses[k];
    imp.t_s = burns[k].t_s;
    imp.dv_eci_mps = applied[k].dv_mps * at[k].v_eci_mps.normalized();
    imp.dv_eci_valid = true;
    imp.dv_rsw_mps = rotation_eci_to_rsw(at[k]) * imp.dv_eci_mps;
  }
  return p;
}

}  // namespace evade::formation
