// The guidance node as a library object (public): the paper-000 close-range evasion law
// (evade/guidance/guidance_law.hpp) and the uplinked burn-plan executor behind the node's LCM
// inputs (node_inputs.hpp) and outputs (evade_thrust_cmd_t, evade_guidance_status_t,
// evade_cmd_ack_t). Its timing loop (fixed rate on absolute deadlines, or lockstep on sim-clock
// ticks) lives in apps/evade_guidance_node; tests and a flight-software integrator drive it
// directly. The state and the cycle are plumbing (internal/node_core.hpp). Requirements:
// docs/GUIDANCE_NODE.md, docs/SECURITY.md. After construction nothing allocates or throws.
#pragma once

#include <cstdint>
#include <memory>

#include <lcm/lcm.h>

#include "evade/auth/keyring.hpp"
#include "evade/autonomy/responder.hpp"
#include "evade/evade_cmd_ack_t.hpp"
#include "evade/evade_guidance_status_t.hpp"
#include "evade/evade_thrust_cmd_t.hpp"
#include "evade/guidance/guidance_law.hpp"
#include "evade/guidance/plan_executor.hpp"
#include "evade/guidance_lcm/input_accounting.hpp"
#include "evade/guidance_lcm/cycle_stats.hpp"
#include "evade/guidance_lcm/node_config.hpp"
#include "evade/guidance_lcm/node_inputs.hpp"
#include "evade/guidance_lcm/node_security.hpp"

namespace evade::guidance_lcm {

namespace internal {
class NodeCore;
}

class GuidanceNode {
 public:
  /// Subscribes on lcm (not owned) and preallocates everything; publishes on out_lcm if given
  /// (e.g. a file:// log in write mode during replay), else on lcm. Starts the anti-replay state
  /// from sec (the state file loaded, or written afresh for --auth-init). Throws
  /// std::invalid_argument on a bad config or a null lcm, std::runtime_error naming the channel
  /// if LCM refuses a subscription, or naming the state file and the problem.
  GuidanceNode(lcm_t* lcm, const NodeConfig& cfg, lcm_t* out_lcm = nullptr,
               const NodeSecurity& sec = NodeSecurity{});
  ~GuidanceNode();
  GuidanceNode(const GuidanceNode&) = delete;
  GuidanceNode& operator=(const GuidanceNode&) = delete;

  /// Handles every message LCM has ready now (non-blocking), up to node.max_drain_per_cycle
  /// messages and node.max_drain_s of wall time.
  /// Returns the number handled, or -1 if LCM reported an error (e.g. end of a log file).
  int drain() noexcept;
  /// Lockstep: blocks up to timeout_ms for a sim-clock tick (inputs that arrive first are
  /// queued; the verification budgets refill every cycle period of waiting). Returns 1 with
  /// *tick_utime set, 0 on timeout, -1 on an LCM error.
  int wait_for_tick(int timeout_ms, std::int64_t* tick_utime) noexcept;
  /// One guidance cycle at now_us. Publishes exactly one command; returns it.
  const evade_thrust_cmd_t& run_cycle(std::int64_t now_us) noexcept;
  /// Writes the authentication state if a command changed it (blocking: the loop calls it
  /// between cycles, never inside one). Commands waiting on it take effect in the next cycle.
  /// Returns 0 (written or nothing to write) or -errno; a failure is counted, and the commands
  /// waiting on it are refused in the next cycle (not_persisted).
  int persist_auth_state() noexcept;
  /// At shutdown: every input still queued and every command not yet executed is counted
  /// (dropped, reason stopped), so the accounting identity holds in the final report.
  void stop() noexcept;

  /// Timing figures from the loop (they go out in the status message).
  void record_compute_time(double us) noexcept;
  void record_wakeup_latency(double us) noexcept;
  void record_overrun() noexcept;

  const InputCounts& counts() const noexcept;
  /// Messages received on one input.
  std::int64_t received(Input in) const noexcept;
  const CycleStats& compute_stats() const noexcept;
  const CycleStats& wakeup_stats() const noexcept;
  const guidance::GuidanceLaw& law() const noexcept;
  const NodeConfig& config() const noexcept;
  const evade_thrust_cmd_t& last_command() const noexcept;
  const evade_guidance_status_t& last_status() const noexcept;
  /// The last acknowledgement published.
  const evade_cmd_ack_t& last_ack() const noexcept;
  std::int64_t cycles() const noexcept;
  /// Commands, status and acknowledgements LCM refused to send (encode or send failure): the
  /// cycle goes on, the next cycle's command supersedes the lost one, and the loss is counted.
  std::int64_t publish_failures() const noexcept;
  std::int64_t watchdog_cycles() const noexcept;
  std::int64_t ticks_received() const noexcept;
  std::int64_t ticks_missed() const noexcept;
  bool armed() const noexcept;
  /// The uplinked burn plan's executor (docs/GUIDANCE_NODE.md PLAN-*).
  const guidance::PlanExecutor& plan_executor() const noexcept;
  const auth::KeyRing& keys() const noexcept;
  std::int64_t auth_persist_failures() const noexcept;
  std::int64_t acks_published() const noexcept;
  std::int64_t acks_unsent() const noexcept;

  /// The onboard conjunction response (docs/AUTONOMY.md): its events, records and counters.
  const autonomy::Responder& responder() const noexcept;
  /// The planning worker's step (AUT-8): runs the job the cycle handed out, if any (the
  /// assessment of one event, milliseconds), and returns true when it ran one. Call it from one
  /// thread beside the cycle's (the node loop's worker), never from inside run_cycle; the cycle
  /// collects the result in a later cycle without waiting.
  bool plan_once() noexcept;
  /// A job is waiting for plan_once or running in it.
  bool planning_busy() const noexcept;
  /// The worker's compute time of the last job collected [us].
  double last_planning_us() const noexcept;
  /// The longest of the worker's jobs collected so far [us].
  double max_planning_us() const noexcept;
  /// Proposals published (evade_cam_proposal_t on EVADE_CAM_PROPOSAL).
  std::int64_t proposals_published() const noexcept;

 private:
  std::unique_ptr<internal::NodeCore> core_;
};

}  // namespace evade::guidance_lcm
