// Internal (not installed): the guidance node's cycle, without its clock: subscribe, queue,
// validate, account, step the law (paper 000 guidance, evade/guidance/guidance_law.hpp),
// publish one command and the status. The timing loop (fixed rate on absolute deadlines, or
// lockstep on sim-clock ticks) lives in apps/evade_guidance_node; tests drive this class
// directly over memq://. Requirements: docs/GUIDANCE_NODE.md (NODE-IN-*, NODE-OUT-*,
// NODE-WD-*, NODE-RT-*).
//
// Authentication (docs/SECURITY.md AUTH-*): the receive callbacks check the security trailer
// of every channel the policy requires (MAC first, then key state and role, then the ARSN)
// within a per-cycle verification budget, and only then copy the bytes in. Commands (plans,
// arm/disarm, key commands) go to the command inbox and take effect only once the anti-replay
// state they advanced is on disk (persist_auth_state(), called by the loop between cycles).
//
// Cycle shape: drain LCM into the bounded queue (receive callback copies raw
// bytes only) → decode + validate + seq/utime checks, newest valid message per channel is
// the candidate (older ones superseded) → watchdog verdict (an input of the law) → step the
// law → encode into a preallocated buffer → publish command (seq +1) → status every
// status_divider cycles. After construction nothing allocates (operator new) or throws.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>

#include <lcm/lcm.h>

#include "evade/evade_angles_t.hpp"
#include "evade/evade_arm_t.hpp"
#include "evade/auth/keyring.hpp"
#include "evade/auth/state_file.hpp"
#include "evade/evade_burn_plan_t.hpp"
#include "evade/evade_guidance_status_t.hpp"
#include "evade/evade_key_cmd_t.hpp"
#include "evade/evade_nav_state_t.hpp"
#include "evade/evade_sim_clock_t.hpp"
#include "evade/evade_thrust_cmd_t.hpp"
#include "evade/guidance/guidance_law.hpp"
#include "evade/guidance/plan_executor.hpp"
#include "evade/guidance_lcm/internal/cycle_stats.hpp"
#include "evade/guidance_lcm/input_accounting.hpp"
#include "evade/guidance_lcm/node_config.hpp"
#include "evade/guidance_lcm/node_security.hpp"
#include "evade/guidance_lcm/internal/input_queue.hpp"
#include "evade/guidance_lcm/internal/command_inbox.hpp"
#include "evade/guidance_lcm/internal/raw_publisher.hpp"
#include "evade/guidance_lcm/internal/seq_tracker.hpp"

namespace evade::guidance_lcm {

enum InputChannel : int { kInAngles = 0, kInNav = 1, kInArm = 2, kInCount = 3 };
/// Channels of the command inbox.
enum CommandChannel : int { kCmdPlan = 0, kCmdArm = 1, kCmdKey = 2, kCmdCount = 3 };

class GuidanceNode {
 public:
  /// Subscribes on lcm (not owned) and preallocates everything; publishes on out_lcm if
  /// given (e.g. a file:// log in write mode during replay), else on lcm. Throws
  /// std::invalid_argument on a bad config or a null lcm, std::runtime_error naming the
  /// channel if LCM refuses a subscription (after undoing the subscriptions already made).
  /// sec holds the keys (none: every message on a channel that must be signed is refused)
  /// and the persisted state, which is loaded here (std::runtime_error if it is malformed).
  GuidanceNode(lcm_t* lcm, const NodeConfig& cfg, lcm_t* out_lcm = nullptr,
               const NodeSecurity& sec = NodeSecurity{});
  ~GuidanceNode();
  GuidanceNode(const GuidanceNode&) = delete;
  GuidanceNode& operator=(const GuidanceNode&) = delete;

  /// Handles every message LCM has ready now (non-blocking), up to max_drain_per_cycle.
  /// Returns the number handled, or -1 if LCM reported an error (e.g. end of a log file).
  int drain() noexcept;
  /// Lockstep: blocks up to timeout_ms for a sim-clock tick (inputs that arrive first are
  /// queued). Returns 1 with *tick_utime set, 0 on timeout, -1 on an LCM error.
  int wait_for_tick(int timeout_ms, std::int64_t* tick_utime) noexcept;
  /// One guidance cycle at now_us. Publishes exactly one command; returns it.
  const evade_thrust_cmd_t& run_cycle(std::int64_t now_us) noexcept;

  /// Writes the authentication state if a command advanced it (blocking: the loop calls it
  /// between cycles, never inside one). Commands waiting on it take effect in the next cycle.
  /// Returns 0 (written or nothing to write) or -errno; a failure is counted, and the commands
  /// waiting on it are refused in the next cycle (not_persisted).
  int persist_auth_state() noexcept;

  /// Timing figures from the loop (they go out in the status message).
  void record_compute_time(double us) noexcept { compute_.add(us); }
  void record_wakeup_latency(double us) noexcept { wakeup_.add(us); }
  void record_overrun() noexcept { compute_.add_overrun(); }

  const InputCounts& counts() const noexcept { return counts_; }
  const CycleStats& compute_stats() const noexcept { return compute_; }
  const CycleStats& wakeup_stats() const noexcept { return wakeup_; }
  const guidance::GuidanceLaw& law() const noexcept { return law_; }
  const NodeConfig& config() const noexcept { return cfg_; }
  const evade_thrust_cmd_t& last_command() const noexcept { return cmd_msg_; }
  const evade_guidance_status_t& last_status() const noexcept { return status_msg_; }
  std::int64_t cycles() const noexcept { return cycles_; }
  /// Commands and status messages LCM refused to send (encode or send failure): the cycle
  /// goes on, the next cycle's command supersedes the lost one, and the loss is counted.
  std::int64_t publish_failures() const noexcept { return publish_failures_; }
  std::int64_t watchdog_cycles() const noexcept { return law_.status().watchdog_cycles; }
  std::int64_t ticks_received() const noexcept { return ticks_received_; }
  std::int64_t ticks_missed() const noexcept { return ticks_missed_; }
  bool armed() const noexcept { return armed_; }
  /// The uplinked burn plan's executor (docs/GUIDANCE_NODE.md PLAN-*).
  const guidance::PlanExecutor& plan_executor() const noexcept { return plan_exec_; }
  const auth::KeyRing& keys() const noexcept { return keys_; }
  std::int64_t auth_persist_failures() const noexcept { return persist_failures_; }

 private:
  struct SubContext {
    GuidanceNode* node;
    int channel;
  };
  lcm_subscription_t* subscribe(const char* channel, lcm_msg_handler_t handler, void* user,
                                bool deep_queue);
  void unsubscribe_all() noexcept;
  static void on_input(const lcm_recv_buf_t* rbuf, const char* channel, void* user) noexcept;
  static void on_clock(const lcm_recv_buf_t* rbuf, const char* channel, void* user) noexcept;
  static void on_command(const lcm_recv_buf_t* rbuf, const char* channel, void* user) noexcept;
  bool authenticate(auth::ArsnSlot slot, const char* channel, const lcm_recv_buf_t* rbuf) noexcept;
  void process_commands(std::int64_t now_us) noexcept;
  void admit_plan(const CommandInbox::Slot& raw, std::int64_t now_us) noexcept;
  void admit_arm(const CommandInbox::Slot& raw, std::int64_t now_us) noexcept;
  void admit_key_cmd(const CommandInbox::Slot& raw, std::int64_t now_us) noexcept;
  bool command_fresh(std::int64_t utime, std::int64_t now_us) noexcept;
  void fill_status(std::int64_t now_us) noexcept;
  void process_queue(std::int64_t now_us) noexcept;
  template <typename Msg>
  bool admit(int channel, const std::uint8_t* data, std::uint32_t size, std::int64_t now_us,
             Msg* msg) noexcept;

  lcm_t* lcm_;
  NodeConfig cfg_;
  guidance::GuidanceLaw law_;
  std::int64_t stale_us_;
  std::int64_t future_us_;
  InputQueue queue_;
  std::array<SubContext, kInCount> ctx_{};
  std::array<SubContext, kCmdCount> cmd_ctx_{};
  std::array<lcm_subscription_t*, kCmdCount> cmd_subs_{};
  std::array<lcm_subscription_t*, kInCount> subs_{};
  lcm_subscription_t* clock_sub_ = nullptr;
  std::array<SeqTracker, kInCount> seq_;
  std::array<std::int64_t, kInCount> dropped_since_accept_{};  // per channel, queue drops
  InputCounts counts_;
  CycleStats compute_;
  CycleStats wakeup_;

  // Candidates of the current cycle (newest valid message per channel).
  std::array<bool, kInCount> have_cand_{};
  evade_angles_t cand_angles_{};
  evade_nav_state_t cand_nav_{};

  // State carried between cycles.
  guidance::GuidanceInput input_{};
  bool armed_ = true;
  bool have_angles_ = false;
  std::int64_t last_angles_utime_ = -1;
  std::int64_t cycles_ = 0;
  std::int64_t publish_failures_ = 0;

  // Commands (plans, arm/disarm, key commands): own bounded inbox, the executor, decode buffers.
  CommandInbox cmd_inbox_;
  guidance::PlanExecutor plan_exec_;
  evade_burn_plan_t plan_msg_{};
  evade_arm_t arm_msg_{};
  evade_key_cmd_t key_msg_{};
  guidance::UplinkedPlan plan_{};
  std::int64_t plan_ack_id_ = 0;
  std::int8_t plan_ack_result_ = 0;
  std::int64_t key_cmd_last_seq_ = 0;
  auth::KeyCmdResult key_cmd_last_result_ = auth::KeyCmdResult::kNone;

  // Authentication (docs/SECURITY.md).
  auth::KeyRing keys_;
  auth::StateFile state_file_;
  std::int8_t auth_required_mask_ = 0;
  int verify_budget_left_ = 0;
  std::uint64_t auth_epoch_ = 0;       ///< +1 per authenticated command that advanced the state
  std::uint64_t persisted_epoch_ = 0;  ///< every command up to this epoch is on disk
  bool persist_failed_ = false;        ///< the last write failed: refuse what waits on it
  std::int64_t persist_failures_ = 0;
  std::int32_t last_command_key_ = 0;

  // Lockstep tick.
  bool tick_pending_ = false;
  std::int64_t tick_utime_ = 0;
  std::int64_t ticks_received_ = 0;
  std::int64_t ticks_missed_ = 0;
  SeqTracker tick_seq_{1000};

  // Outputs, preallocated.
  std::int64_t cmd_seq_ = 0;
  std::int64_t status_seq_ = 0;
  evade_thrust_cmd_t cmd_msg_{};
  evade_guidance_status_t status_msg_{};
  RawPublisher<evade_thrust_cmd_t> cmd_pub_;
  RawPublisher<evade_guidance_status_t> status_pub_;
};

}  // namespace evade::guidance_lcm
