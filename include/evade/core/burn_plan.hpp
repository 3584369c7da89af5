// An impulsive burn plan as the planners hand it on: up to kMaxImpulses burns (RSW and,
// when known, ECI Δv) at times after the plan's epoch, the code of the planner that made it,
// and the observability planner's extras. Fixed size, no LCM: the message form is
// evade_burn_plan_t (guidance_lcm/burn_plan_convert.hpp).
#pragma once

#include <array>
#include <cstdint>

#include "evade/core/state.hpp"

namespace evade {

/// Planner that produced a plan; 1..4: the number of the paper the planner implements.
enum class PlanSource : int {
  kUnknown = 0,
  kThreatArea = 1,     ///< evade plan threat-area (paper 001)
  kFormation = 3,      ///< evade plan formation (paper 003)
  kObservability = 4,  ///< evade plan observability (paper 004), NLopt ISRES (+ polish)
  kCollisionAvoidance = 5,  ///< evade plan cam: minimum-dv burn for a Pc threshold (issue 12)
};

/// Objective the observability planner optimized (codes of evade_burn_plan_t's OBJECTIVE_*).
enum class PlanObjective : int {
  kPaper = 0,      ///< paper 004 eq. 23, maximized
  kLosChange = 1,  ///< summed change of the measured LOS angles, minimized
  kEstimation = 2, ///< chaser's 1-sigma posterior position major axis, maximized
};

struct ImpulsiveBurn {
  double t_s = 0.0;                  ///< burn time after the plan's epoch [s]
  Vec3 dv_rsw_mps = Vec3::Zero();    ///< Δv in RSW (= LVLH: x radial out, y along track, z normal) [m/s]
  bool dv_eci_valid = false;         ///< true if dv_eci_mps is filled (needs an inertial state)
  Vec3 dv_eci_mps = Vec3::Zero();    ///< Δv in ECI (J2000 axes) [m/s]; zero when not valid
};

/// Extras of a plan from the observability planner (valid only for PlanSource::kObservability).
struct ObservabilityPlanInfo {
  bool valid = false;          ///< false: the plan comes from another planner
  double eps_rad = 0.0;        ///< burn elevation ε, paper-004 frame [rad]
  double theta_rad = 0.0;      ///< burn azimuth θ, paper-004 frame [rad]
  int objective = static_cast<int>(PlanObjective::kPaper);  ///< PlanObjective code
  double objective_value = 0.0;  ///< PAPER [-], LOS_CHANGE [rad], ESTIMATION [m]
  int evaluations = 0;         ///< objective evaluations spent by the planner
};

struct BurnPlan {
  static constexpr int kMaxImpulses = 8;

  std::int64_t plan_id = 0;    ///< the publisher's plan number (+1 per plan)
  std::array<ImpulsiveBurn, kMaxImpulses> impulses{};  ///< the first n_impulses are used
  int n_impulses = 0;          ///< 0 .. kMaxImpulses
  int source = static_cast<int>(PlanSource::kUnknown);  ///< PlanSource code
  ObservabilityPlanInfo observability;  ///< filled by the observability planner only
};

}  // namespace evade
