// Onboard execution of an uplinked burn plan (core/burn_plan.hpp, message evade_burn_plan_t;
// requirements PLAN-* in docs/GUIDANCE_NODE.md). Pure: no LCM, no clock, no allocation.
//
// Validation (load): a plan is accepted only if it is finite, in a known frame (RSW, or
// ECI with every impulse's ECI Δv filled), has 1..kMaxImpulses impulses, its burns start
// in the future, are ordered and do not overlap (≥ one cycle apart), its total |Δv| fits in
// the Δv budget not yet spent, each burn at the thrust limit fits in the burn-time limit,
// its plan id is newer than the last accepted one, and the node is armed. Otherwise it is
// rejected with a PlanReject reason, counted per reason; the active plan is unchanged.
//
// Execution (step, once per guidance cycle): impulse i of |Δv_i| becomes a finite burn of
// N_i = ceil(|Δv_i| / (a_max T)) whole cycles (T the guidance cycle, a_max the thrust
// limit) at a_i = |Δv_i| / (N_i T) ≤ a_max, centred on its planned time: it starts at the
// first cycle at or after  t_i − N_i T / 2 − T / 2,  so the centre is within T/2 of t_i on a
// regular clock. Direction: the RSW Δv turned into ECI with the current navigation state
// (the RSW frame of the own orbit, every cycle), or the plan's fixed ECI Δv. Δv delivered
// is accounted like the law's: accel × the time the command was in force (now − previous
// step).
//
// Ends: completed; cancelled by a disarm; pre-empted by close-range evasion (the law in
// EVADE: paper 000 wins and the plan is abandoned); abandoned when the law is SAFE (invalid
// or stale inputs) during a burn or a burn's start cycle passes; superseded by a newer plan.
#pragma once

#include <array>
#include <cstdint>

#include "evade/core/burn_plan.hpp"
#include "evade/core/state.hpp"
#include "evade/guidance/guidance_law.hpp"

namespace evade::guidance {

/// Frame of the Δv the executor flies (evade_burn_plan_t.FRAME_*).
enum class PlanFrame : std::uint8_t {
  kRsw = 0,  ///< impulses' dv_rsw_mps, rotated into ECI with the current nav every cycle
  kEci = 1,  ///< impulses' dv_eci_mps (every impulse must have dv_eci_valid)
};

/// Why a plan was not accepted (one counter each; codes as evade_burn_plan_t.REJECT_*).
enum class PlanReject : std::uint8_t {
  kNone = 0,
  kMalformed = 1,        ///< message flags or codes out of range (source, objective, 0/1 flags)
  kImpulseCount = 2,     ///< n_impulses outside 1..kMaxImpulses
  kNotFinite = 3,        ///< NaN or Inf in a time or a Δv
  kUnknownFrame = 4,     ///< frame not RSW/ECI, or ECI without every impulse's ECI Δv
  kBurnInPast = 5,       ///< a burn's first cycle is not after now
  kNotOrdered = 6,       ///< impulse times not strictly increasing
  kOverlapping = 7,      ///< two burns closer than one cycle
  kOverBudget = 8,       ///< total |Δv| exceeds the Δv budget not yet spent
  kOverThrustLimit = 9,  ///< a burn at the thrust limit would last longer than max_burn_s
  kNotNewer = 10,        ///< plan id not greater than the last accepted plan's
  kDisarmed = 11,        ///< the node is disarmed: it executes nothing
  kCount = 12
};

enum class PlanState : std::uint8_t {
  kIdle = 0,     ///< no plan accepted yet
  kWaiting = 1,  ///< accepted, waiting for the next burn
  kBurning = 2,  ///< commanding a burn this cycle
  kEnded = 3,    ///< finished: see PlanEnd
};

enum class PlanEnd : std::uint8_t {
  kNone = 0,             ///< not ended
  kCompleted = 1,        ///< every impulse delivered
  kCancelledDisarm = 2,  ///< disarmed while the plan was active
  kPreemptedEvasion = 3, ///< the law went EVADE (paper 000 close-range evasion)
  kAbandonedSafe = 4,    ///< the law went SAFE during a burn
  kMissedStart = 5,      ///< a burn's start cycle passed without the burn starting
  kSuperseded = 6,       ///< a newer plan was accepted
  kCancelledOnboard = 7, ///< the onboard conjunction response withdrew its own burn (docs/AUTONOMY.md)
};

const char* plan_reject_name(PlanReject r) noexcept;
const char* plan_end_name(PlanEnd e) noexcept;

/// What the executor needs of the guidance configuration (same parameters, no new ones).
struct PlanExecutorConfig {
  double max_accel_mps2 = 1.0;  ///< thrust limit (guidance.max_accel_mps2)
  double cycle_s = 0.02;        ///< guidance cycle T (1 / guidance.rate_hz)
  double dv_budget_mps = 100.0; ///< guidance.dv_budget_mps, shared by the law and the plans
  double max_burn_s = 600.0;    ///< guidance.max_burn_s, per burn
  static PlanExecutorConfig from(const GuidanceConfig& g) noexcept;
};

/// A plan as uplinked: the impulses, the utime of their epoch (t = 0) and the frame.
struct UplinkedPlan {
  BurnPlan plan;
  std::int64_t epoch_utime_us = 0;
  PlanFrame frame = PlanFrame::kRsw;
};

/// The plan's thrust this cycle (accel 0: none).
struct PlanThrust {
  Vec3 u_eci = Vec3::Zero();
  double accel_mps2 = 0.0;
};

struct PlanExecStatus {
  std::int64_t plan_id = 0;  ///< active (or last ended) plan
  PlanState state = PlanState::kIdle;
  PlanEnd end = PlanEnd::kNone;
  int n_impulses = 0;
  int impulses_done = 0;
  std::array<double, BurnPlan::kMaxImpulses> dv_delivered_mps{};  ///< per impulse [m/s]
  std::array<std::int64_t, BurnPlan::kMaxImpulses> burn_start_us{};  ///< first thrust cycle
  std::array<std::int64_t, BurnPlan::kMaxImpulses> burn_end_us{};    ///< thrust ended
  double dv_total_mps = 0.0;       ///< delivered by every plan so far [m/s]
  PlanReject last_reject = PlanReject::kNone;
  std::int64_t accepted = 0;
  std::array<std::int64_t, static_cast<int>(PlanReject::kCount)> rejected{};  ///< per reason
};

class PlanExecutor {
 public:
  explicit PlanExecutor(const PlanExecutorConfig& cfg) noexcept;

  /// Validates p at now_us (dv_used_mps: Δv the law has spent); accepts it (superseding an
  /// active plan) or counts the rejection. Returns kNone when accepted.
  PlanReject load(const UplinkedPlan& p, std::int64_t now_us, bool armed,
                  double dv_used_mps) noexcept;
  /// Counts a rejection decided before load (the message edge: malformed, not finite).
  void count_rejection(PlanReject r) noexcept;
  /// Ends the active plan (no effect when none is active).
  void cancel(PlanEnd why) noexcept;
  /// One cycle, after the law's step: law_mode is the law's mode this cycle.
  PlanThrust step(const NavState& nav, bool armed, GuidanceMode law_mode,
                  std::int64_t now_us) noexcept;

  bool active() const noexcept {
    return status_.state == PlanState::kWaiting || status_.state == PlanState::kBurning;
  }
  const PlanExecStatus& status() const noexcept { return status_; }

 private:
  struct Burn {
    std::int64_t first_cycle_us = 0;  // earliest cycle time that may start it
    int cycles = 0;                   // N
    double accel_mps2 = 0.0;          // a = |Δv| / (N T)
    Vec3 dir = Vec3::Zero();          // unit Δv in the plan's frame (zero for Δv = 0)
  };
  PlanReject check(const UplinkedPlan& p, std::int64_t now_us, bool armed,
                   double dv_used_mps) const noexcept;
  PlanReject check_burns(const UplinkedPlan& p, std::int64_t now_us) const noexcept;
  Burn burn_of(const UplinkedPlan& p, int i) const noexcept;
  void account(std::int64_t now_us) noexcept;
  PlanThrust thrust(const NavState& nav) const noexcept;
  PlanThrust next_burn(const NavState& nav, GuidanceMode law_mode, std::int64_t now_us) noexcept;

  PlanExecutorConfig cfg_;
  std::int64_t cycle_us_ = 0;
  PlanFrame frame_ = PlanFrame::kRsw;
  std::array<Burn, BurnPlan::kMaxImpulses> burns_{};
  int current_ = 0;        // impulse being flown or waited for
  int cycles_left_ = 0;    // of the current burn
  bool have_last_id_ = false;
  std::int64_t last_id_ = 0;
  double prev_accel_mps2_ = 0.0;  // plan thrust commanded at the previous step
  std::int64_t prev_us_ = 0;
  PlanExecStatus status_;
};

/// The command flown: the law's, unless the plan thrusts this cycle (then its direction and
/// acceleration; mode and reason stay the law's — the plan shows in the status).
ThrustCommand merge_plan_thrust(const ThrustCommand& law_cmd, const PlanThrust& plan) noexcept;

}  // namespace evade::guidance
