// Executing an uplinked burn plan in the simulator (docs/GUIDANCE_NODE.md PLAN-SIM-1): the own
// satellite and one other object under two-body (+ J2) truth, one guidance exchange per cycle
// (nav from the truth, no angle measurement: the close-range law stays idle), the command
// applied through the actuator model as a zero-order hold. The guidance behind the endpoint
// (the node over LCM, or the in-process law + plan executor) flies the plan; this records
// every burn as the actuator delivered it. Times are seconds from the run's epoch (t = 0),
// whose utime is PlanRunConfig::utime0_us (kPlanRunUtime0 unless a run sets its own, e.g. a
// calendar time for a run that the ground's CDMs date).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "evade/core/burn_plan.hpp"
#include "evade/guidance/plan_executor.hpp"
#include "evade/dynamics/dop853.hpp"
#include "evade/dynamics/gravity.hpp"
#include "evade/sim/guidance_endpoint.hpp"
#include "evade/sim/sim_config.hpp"

namespace evade::sim {

inline constexpr std::int64_t kPlanRunUtime0 = 1'000'000'000;  ///< utime of t = 0 [us]

struct PlanRunConfig {
  StateEci satellite0;  ///< own satellite at t = 0 (it executes the plan)
  StateEci other0;      ///< the other object (chaser, debris) at t = 0
  GravityModel gravity = GravityModel::kTwoBody;
  EarthModel earth = kEarthDefault;
  double rate_hz = 50.0;       ///< guidance exchange rate
  std::int64_t utime0_us = kPlanRunUtime0;  ///< utime of t = 0 [us] (> 0)
  double duration_s = 100.0;   ///< run length
  ActuatorConfig actuator;
  AdaptiveOptions integrator = AdaptiveOptions::tight();
  /// Times [s] at which both objects are recorded (PlanRunResult::samples): each at the
  /// first cycle start at or after it (or the run's end); finite, ascending, in [0, duration].
  std::vector<double> sample_t_s;
};

/// Both objects' truth at one cycle start.
struct PlanRunSample {
  double t_s = 0.0;  ///< the cycle start the sample was taken at [s]
  StateEci satellite;
  StateEci other;
};

/// One burn as the actuator applied it: a run of consecutive cycles with thrust.
struct DeliveredBurn {
  double t_start_s = 0.0;
  double t_end_s = 0.0;
  Vec3 dv_eci_mps = Vec3::Zero();  ///< ∫ a dt [m/s]
  StateEci satellite_at_centre;    ///< truth at the cycle nearest the burn's centre
};

struct PlanRunResult {
  std::vector<DeliveredBurn> burns;
  StateEci satellite_end;
  StateEci other_end;
  std::vector<PlanRunSample> samples;  ///< one per PlanRunConfig::sample_t_s
  long cycles = 0;
  guidance::GuidanceStatus final_status;
  bool has_final_status = false;
};

/// Called before each exchange with the cycle index and its utime (e.g. to uplink a plan).
using PlanRunHook = std::function<void(long, std::int64_t)>;

/// Runs cfg. Throws std::invalid_argument on a bad config, std::runtime_error if the
/// integration fails.
PlanRunResult run_plan_simulation(const PlanRunConfig& cfg, GuidanceEndpoint& guidance,
                                  const PlanRunHook& before_exchange = {});

/// Truth without thrust from t = 0 to t_s (both objects), for reference trajectories.
void propagate_unforced(const PlanRunConfig& cfg, double t_s, StateEci* satellite,
                        StateEci* other);

/// In-process guidance with a plan: the paper-000 law (armed) plus the plan executor, the
/// plan loaded at the first exchange with its epoch at epoch_utime_us and the given frame.
/// exchange throws std::invalid_argument naming the executor's reason if it rejects the plan.
std::unique_ptr<GuidanceEndpoint> make_in_process_plan_endpoint(
    const guidance::GuidanceConfig& cfg, const BurnPlan& plan, std::int64_t epoch_utime_us,
    guidance::PlanFrame frame = guidance::PlanFrame::kRsw);

/// A plan run on a simulation scenario's objects (`evade sim --plan`): the own satellite and
/// the other object at the scenario's epoch, its gravity, Earth, actuator, integrator and
/// guidance rate; the plan's t = 0 is epoch_s after the run starts; the run lasts until one
/// second after the last burn can have ended (its planned time plus the burn at the thrust
/// limit max_accel_mps2, rounded up to whole cycles, plus two cycles), plus after_s.
/// Throws std::invalid_argument for a plan without impulses, epoch_s or after_s not finite
/// and >= 0, or a run longer than the simulator's 1e7 s.
PlanRunConfig plan_run_config(const SimConfig& sim, const BurnPlan& plan, double epoch_s,
                              double after_s);

}  // namespace evade::sim
