// The node's authority over an onboard avoidance burn (docs/AUTONOMY.md AUT-7): the state of
// every tracked conjunction, the ground's decisions and the node's policy, as a pure state
// machine the node drives once per cycle. It does no planning itself: it hands one planning
// job at a time to the node's worker (next_job), which runs assess_event (response.hpp) beside
// the cycle and returns the result (complete); and it asks the node for at most one action per
// cycle (tick: load a burn into the plan executor, or cancel one).
//
// The rules:
//  - A newer version of an event replaces the older one (the old version is reported
//    superseded once); a burn scheduled for the old version is cancelled. A new or replaced
//    event sends every other event's unvetoed proposal back to assessment, since its burn was
//    not checked against the newcomer; a result computed before that is discarded (stale).
//  - A proposal is ready only before the event's veto deadline (a later one needs the ground:
//    the ground must see every burn before it can fly). Its burn is after the deadline.
//  - Policy veto (the default): at the deadline the proposal is loaded unless vetoed.
//    Policy approve: loaded only when approved before the deadline, else expired
//    (not_approved). Policy off: proposals are reported (report_only), never loaded, and
//    setting off cancels a loaded burn (the operator's procedure when the other operator
//    manoeuvres). Setting veto or approve again revives a report_only proposal whose deadline
//    has not passed.
//  - A decision names the event and the proposal: a veto holds for the event's version
//    whatever it is re-planned to; an approval is of that proposal only (a re-plan needs a new
//    one); the latest decision before the deadline counts; after it, none is taken.
//  - One onboard burn is loaded at a time, and none while another plan is active in the
//    executor (the ground's): such a deadline gives needs_ground (executor_busy).
// Flight code: no allocation, no exceptions, loops bounded by kMaxEvents.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "evade/autonomy/event_table.hpp"
#include "evade/autonomy/response.hpp"

namespace evade::autonomy {

/// The ground's decision (evade_cam_decision_t, authenticated before it gets here).
struct DecisionCommand {
  enum class Kind : std::uint8_t { kVeto = 1, kApprove = 2, kSetAutonomy = 3 };
  Kind kind = Kind::kVeto;
  std::int64_t event_id = 0;
  std::int64_t proposal_id = 0;
  std::uint8_t autonomy = 0;  ///< kSetAutonomy: Policy's value
};

/// What became of a decision (evade_cmd_ack_t's detail).
enum class DecisionResult : std::uint8_t {
  kApplied = 0,
  kBadDecision,    ///< unknown kind or autonomy value
  kUnknownEvent,   ///< the event is not tracked
  kNotPending,     ///< the event has no proposal awaiting a decision
  kWrongProposal,  ///< the event's proposal is another one (re-planned or a new version)
  kPastDeadline,   ///< the veto deadline has passed
  kAutonomyOff,    ///< an approval while the policy is off
  kAlreadyApplied, ///< that very veto or approval of that proposal is in force (a retransmission)
};
const char* decision_result_name(DecisionResult r) noexcept;

/// What became of an uplinked event.
enum class EventResult : std::uint8_t {
  kTracked = 0,    ///< a new event in its own slot
  kReplaced,       ///< a newer version of a tracked event
  kBadEvent,       ///< check_event found a problem (EventProblem)
  kNotNewer,       ///< that version or a newer one is tracked
  kTableFull,      ///< every slot holds a live event
  kAlreadyTracked, ///< the very event tracked, sent again (a retransmission): nothing changes
};
const char* event_result_name(EventResult r) noexcept;

/// What the node does this cycle.
struct ResponderAction {
  enum class Kind : std::uint8_t { kNone = 0, kSchedule, kCancel };
  Kind kind = Kind::kNone;
  std::size_t slot = kMaxEvents;
  std::int64_t event_id = 0;
  std::int64_t proposal_id = 0;
  std::int64_t burn_us = 0;       ///< kSchedule: the impulse's centre
  Vec3 dv_eci_mps = Vec3::Zero();  ///< kSchedule
  std::int64_t plan_id = 0;        ///< kCancel: the plan to end
};

/// One tracked event's response: what the node publishes (evade_cam_proposal_t).
struct ResponseRecord {
  std::int64_t event_id = 0;
  std::int32_t version = 0;
  ResponseState state = ResponseState::kAssessing;
  ResponseReason reason = ResponseReason::kNone;
  std::int64_t proposal_id = 0;      ///< 0: none
  std::int64_t veto_deadline_us = 0;
  std::int64_t plan_id = 0;          ///< the plan loaded for it, 0 before
  bool approved = false;             ///< the ground approved proposal_id
  std::uint32_t generation = 0;      ///< +1 whenever it goes back to assessment
  Assessment assessment{};
  std::int32_t superseded_version = 0;  ///< > 0: report that version superseded once
  std::int64_t superseded_proposal_id = 0;
  bool changed = true;                  ///< publish it now
};

struct ResponderCounters {
  std::int64_t events_tracked = 0, events_replaced = 0;
  std::int64_t events_bad = 0, events_not_newer = 0, events_table_full = 0, events_again = 0;
  std::int64_t decisions_applied = 0, decisions_refused = 0, decisions_again = 0;
  std::int64_t jobs = 0, stale_results = 0, proposals = 0, schedules = 0, cancels = 0;
};

class Responder {
 public:
  explicit Responder(Policy policy) noexcept : policy_(policy) {}

  /// An authenticated event at now_us; *problem (if given) is check_event's answer.
  EventResult receive_event(const ConjunctionEvent& e, std::int64_t now_us,
                            EventProblem* problem = nullptr) noexcept;
  DecisionResult receive_decision(const DecisionCommand& d, std::int64_t now_us) noexcept;

  /// The next event to assess (earliest TCA first), none while one is with the worker. The
  /// node fills job->nav_valid and job->x_nav_eci.
  bool next_job(std::int64_t now_us, PlanningJob* job) noexcept;
  /// The worker's result for job; false when it is stale (discarded and counted).
  bool complete(const PlanningJob& job, const Assessment& a, std::int64_t now_us) noexcept;

  /// At most one action for this cycle. executor_busy: another plan is active there.
  ResponderAction tick(std::int64_t now_us, bool executor_busy) noexcept;
  /// The node's answer to a kSchedule: the plan id loaded, or accepted = false.
  void scheduled(std::size_t slot, std::int64_t proposal_id, std::int64_t plan_id, bool accepted) noexcept;
  /// The plan executor ended plan_id: completed, or not (abandoned, pre-empted, missed).
  void plan_ended(std::int64_t plan_id, bool completed) noexcept;

  Policy policy() const noexcept { return policy_; }
  bool tracked(std::size_t slot) const noexcept { return table_.slot(slot).used; }
  const ResponseRecord& record(std::size_t slot) const noexcept { return rec_[slot]; }
  /// The node published the slot's record (and its superseded notice).
  void published(std::size_t slot) noexcept;
  const ResponderCounters& counters() const noexcept { return counters_; }

 private:
  void set_policy(Policy p, std::int64_t now_us) noexcept;
  void replan_others(std::size_t except) noexcept;
  DecisionResult decide(const DecisionCommand& d, std::int64_t now_us) noexcept;
  bool tick_slot(std::size_t i, std::int64_t now_us, bool executor_busy, ResponderAction* act) noexcept;
  void set(std::size_t i, ResponseState s, ResponseReason r) noexcept;

  EventTable table_;
  std::array<ResponseRecord, kMaxEvents> rec_;  // each by its member initializers
  Policy policy_;
  std::size_t in_flight_ = kMaxEvents;    ///< the slot whose job the worker holds
  std::size_t loaded_slot_ = kMaxEvents;  ///< the slot whose burn is loaded
  std::int64_t pending_cancel_plan_ = 0;  ///< a plan to cancel at the next tick
  std::int64_t last_proposal_id_ = 0;
  ResponderCounters counters_;
};

}  // namespace evade::autonomy
