// Internal (not installed): the guidance node's state and cycle behind the public
// guidance_lcm::GuidanceNode (guidance_node.hpp). Receive, queue, authenticate, validate,
// account, step the law (paper 000 guidance, evade/guidance/guidance_law.hpp), publish one
// command, the signed acknowledgements and the signed status. Requirements: docs/GUIDANCE_NODE.md
// (NODE-IN-*, NODE-OUT-*, NODE-WD-*, NODE-RT-*), docs/SECURITY.md (AUTH-*, ARSN-*, TM-*).
//
// The inputs are the rows of node_inputs.hpp; one receive callback serves them all and hands the
// bytes to the row's kind: a sensor goes to the bounded input queue, a command to the command
// inbox, a tick to the lockstep clock. Every required row is authenticated in the callback
// within its channel's verification budget (MAC first, then key state and role, then the ARSN
// compared but not yet advanced: auth::KeyRing::check); its ARSN is committed only when the
// message is admitted in full in the cycle (decoded, fresh), so a refused message changes
// nothing. Commands take effect once their committed ARSN is on disk (persist_auth_state(),
// called by the loop between cycles) and are acknowledged with evade_cmd_ack_t, signed with the
// node's telemetry key, naming the command's key id, ARSN and MAC.
//
// Cycle shape: process the input queue (newest valid message per sensor is the candidate, older
// ones superseded) → admit new commands and execute the persisted ones → watchdog verdict → step
// the law → publish the command (seq +1) → publish the ready acknowledgements → status every
// status_divider cycles → refill the verification budgets. After construction nothing allocates
// (operator new) or throws.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>

#include <lcm/lcm.h>

#include "evade/auth/keyring.hpp"
#include "evade/auth/state_file.hpp"
#include "evade/evade_angles_t.hpp"
#include "evade/evade_arm_t.hpp"
#include "evade/autonomy/responder.hpp"
#include "evade/evade_burn_plan_t.hpp"
#include "evade/evade_cam_decision_t.hpp"
#include "evade/evade_cam_proposal_t.hpp"
#include "evade/evade_conjunction_t.hpp"
#include "evade/evade_cmd_ack_t.hpp"
#include "evade/evade_guidance_status_t.hpp"
#include "evade/evade_key_cmd_t.hpp"
#include "evade/evade_nav_state_t.hpp"
#include "evade/evade_sim_clock_t.hpp"
#include "evade/evade_thrust_cmd_t.hpp"
#include "evade/guidance/guidance_law.hpp"
#include "evade/guidance/plan_executor.hpp"
#include "evade/guidance_lcm/input_accounting.hpp"
#include "evade/guidance_lcm/internal/ack_outbox.hpp"
#include "evade/guidance_lcm/internal/command_inbox.hpp"
#include "evade/guidance_lcm/cycle_stats.hpp"
#include "evade/guidance_lcm/internal/input_queue.hpp"
#include "evade/guidance_lcm/internal/planning_mailbox.hpp"
#include "evade/guidance_lcm/internal/raw_publisher.hpp"
#include "evade/guidance_lcm/internal/seq_tracker.hpp"
#include "evade/guidance_lcm/internal/verify_budget.hpp"
#include "evade/guidance_lcm/node_config.hpp"
#include "evade/guidance_lcm/node_inputs.hpp"
#include "evade/guidance_lcm/node_security.hpp"

namespace evade::guidance_lcm::internal {

class NodeCore {
 public:
  NodeCore(lcm_t* lcm, const NodeConfig& cfg, lcm_t* out_lcm, const NodeSecurity& sec);
  ~NodeCore();
  NodeCore(const NodeCore&) = delete;
  NodeCore& operator=(const NodeCore&) = delete;

  int drain() noexcept;
  int wait_for_tick(int timeout_ms, std::int64_t* tick_utime) noexcept;
  const evade_thrust_cmd_t& run_cycle(std::int64_t now_us) noexcept;
  int persist_auth_state() noexcept;
  void stop() noexcept;

  void record_compute_time(double us) noexcept { compute_.add(us); }
  void record_wakeup_latency(double us) noexcept { wakeup_.add(us); }
  void record_overrun() noexcept { compute_.add_overrun(); }

  const InputCounts& counts() const noexcept { return counts_; }
  std::int64_t received(Input in) const noexcept { return received_[index(in)]; }
  const CycleStats& compute_stats() const noexcept { return compute_; }
  const CycleStats& wakeup_stats() const noexcept { return wakeup_; }
  const guidance::GuidanceLaw& law() const noexcept { return law_; }
  const NodeConfig& config() const noexcept { return cfg_; }
  const evade_thrust_cmd_t& last_command() const noexcept { return cmd_msg_; }
  const evade_guidance_status_t& last_status() const noexcept { return status_msg_; }
  const evade_cmd_ack_t& last_ack() const noexcept { return last_ack_; }
  std::int64_t cycles() const noexcept { return cycles_; }
  std::int64_t publish_failures() const noexcept { return publish_failures_; }
  std::int64_t ticks_received() const noexcept { return ticks_received_; }
  std::int64_t ticks_missed() const noexcept { return ticks_missed_; }
  bool armed() const noexcept { return armed_; }
  const guidance::PlanExecutor& plan_executor() const noexcept { return plan_exec_; }
  const auth::KeyRing& keys() const noexcept { return keys_; }
  std::int64_t auth_persist_failures() const noexcept { return persist_failures_; }
  std::int64_t acks_published() const noexcept { return acks_published_; }
  std::int64_t acks_unsent() const noexcept { return acks_unsent_; }
  const autonomy::Responder& responder() const noexcept { return responder_; }
  bool plan_once() noexcept { return planner_.work(); }
  bool planning_busy() const noexcept { return planner_.busy(); }
  double last_planning_us() const noexcept { return last_planning_us_; }
  double max_planning_us() const noexcept { return max_planning_us_; }
  std::int64_t proposals_published() const noexcept { return proposal_seq_; }

 private:
  struct SubContext {
    NodeCore* node;
    Input input;
  };
  static std::size_t index(Input in) noexcept { return static_cast<std::size_t>(in); }

  // node_core.cpp: construction, the subscribe loop, the cycle.
  lcm_subscription_t* subscribe(const InputRow& row);
  void unsubscribe_all() noexcept;

  // node_receive.cpp: the receive callback and authentication.
  static void on_message(const lcm_recv_buf_t* rbuf, const char* channel, void* user) noexcept;
  void receive(const InputRow& row, const std::uint8_t* data, std::uint32_t size) noexcept;
  bool authenticate(const InputRow& row, const std::uint8_t* data, std::uint32_t size,
                    auth::TrailerView* t) noexcept;
  void receive_sensor(const InputRow& row, const std::uint8_t* data, std::uint32_t size) noexcept;
  void receive_tick(const InputRow& row, const std::uint8_t* data, std::uint32_t size) noexcept;
  void receive_command(const InputRow& row, const std::uint8_t* data,
                       std::uint32_t size) noexcept;
  bool commit_arsn(std::int32_t key_id, auth::ArsnSlot slot, std::int64_t arsn) noexcept;

  // node_sensors.cpp: the sensor queue's messages into the law's input.
  void process_queue(std::int64_t now_us) noexcept;
  template <typename Msg>
  bool admit_sensor(const RawMessage& raw, std::int64_t now_us, Msg* msg) noexcept;
  bool admit_seq(Input in, std::int64_t seq, std::int64_t utime) noexcept;

  // node_commands.cpp: admission, persistence, execution.
  void process_commands(std::int64_t now_us) noexcept;
  void admit_command(CommandInbox::Slot& slot, std::int64_t now_us) noexcept;
  bool admit_unsigned_arm(std::int64_t now_us) noexcept;
  bool decode_command(CommandInbox::Slot& slot) noexcept;
  void execute_command(CommandInbox::Slot& slot, std::int64_t now_us) noexcept;
  void execute_plan(CommandInbox::Slot& slot, std::int64_t now_us) noexcept;
  void execute_arm(CommandInbox::Slot& slot, std::int64_t now_us) noexcept;
  void execute_key_cmd(CommandInbox::Slot& slot, std::int64_t now_us) noexcept;
  void refuse(CommandInbox::Slot& slot, Verdict v, Reason r, std::int16_t detail,
              std::int64_t now_us) noexcept;
  // node_autonomy.cpp: the onboard conjunction response (docs/AUTONOMY.md).
  void execute_conjunction(CommandInbox::Slot& slot, std::int64_t now_us) noexcept;
  void execute_decision(CommandInbox::Slot& slot, std::int64_t now_us) noexcept;
  void step_autonomy(std::int64_t now_us) noexcept;
  void hand_out_job(std::int64_t now_us) noexcept;
  void watch_onboard_plan() noexcept;
  void schedule_burn(const autonomy::ResponderAction& act, std::int64_t now_us) noexcept;
  void cancel_burn(const autonomy::ResponderAction& act) noexcept;
  void publish_proposals(std::int64_t now_us) noexcept;
  void publish_proposal(const autonomy::ResponseRecord& r, bool superseded,
                        std::int64_t now_us) noexcept;

  // node_telemetry.cpp: acknowledgements and the status, signed.
  void ack(const CommandInbox::Slot& slot, std::int8_t outcome, Reason r, std::int16_t detail,
           std::uint64_t epoch, std::int64_t now_us) noexcept;
  void ack_refused_in_callback(const InputRow& row, const auth::TrailerView& t, Reason r) noexcept;
  void fill_ack(Input in, std::int32_t key_id, std::int64_t arsn, const std::uint8_t* mac,
                std::int8_t outcome, Reason r, std::int16_t detail, std::int64_t now_us,
                evade_cmd_ack_t* a) const noexcept;
  void fail_waiting_acks() noexcept;
  void publish_acks() noexcept;
  void fill_status(std::int64_t now_us) noexcept;
  void fill_status_keys() noexcept;

  lcm_t* lcm_;
  NodeConfig cfg_;
  guidance::GuidanceLaw law_;
  std::int64_t stale_us_;
  std::int64_t future_us_;
  std::int64_t refill_window_us_;
  std::int64_t drain_us_;
  InputQueue queue_;
  std::array<SubContext, kInputCount> ctx_{};
  std::array<lcm_subscription_t*, kInputCount> subs_{};
  std::array<SeqTracker, kInputCount> seq_;
  std::array<std::int64_t, kInputCount> dropped_since_accept_{};  // per channel, queue drops
  std::array<std::int64_t, kInputCount> received_{};               // per input
  InputCounts counts_;
  CycleStats compute_;
  CycleStats wakeup_;

  // Candidates of the current cycle (newest valid message per sensor).
  bool have_angles_cand_ = false;
  bool have_nav_cand_ = false;
  evade_angles_t cand_angles_{};
  evade_nav_state_t cand_nav_{};

  // State carried between cycles.
  guidance::GuidanceInput input_{};
  bool armed_ = true;
  bool have_angles_ = false;
  std::int64_t last_angles_utime_ = -1;
  std::int64_t cycles_ = 0;
  std::int64_t publish_failures_ = 0;
  std::int64_t last_cycle_us_ = 0;  // the cycle time of the last cycle (acks of callbacks)

  // Commands: the inbox, the executor, decode buffers, the plan in force's bytes.
  CommandInbox cmd_inbox_;
  guidance::PlanExecutor plan_exec_;
  evade_burn_plan_t plan_msg_{};
  evade_arm_t arm_msg_{};
  evade_key_cmd_t key_msg_{};
  guidance::UplinkedPlan plan_{};
  std::int64_t plan_ack_id_ = 0;
  std::int8_t plan_ack_result_ = 0;
  std::uint32_t plan_in_force_size_ = 0;  ///< authenticated bytes of the plan in force
  std::array<std::uint8_t, kMaxCommandBytes> plan_in_force_{};
  std::int64_t key_cmd_last_seq_ = 0;
  evade_conjunction_t conj_msg_{};
  evade_cam_decision_t decision_msg_{};
  // The onboard conjunction response: the responder, the planning worker's mailbox, the jobs
  // going out and coming back, the onboard burn the executor flies (0: none), the proposals.
  autonomy::Responder responder_;
  PlanningMailbox planner_;
  autonomy::ConjunctionEvent event_{};
  autonomy::DecisionCommand decision_{};
  autonomy::PlanningJob job_out_{};
  autonomy::PlanningJob job_back_{};
  autonomy::Assessment assessment_back_{};
  guidance::UplinkedPlan onboard_plan_{};
  std::int64_t onboard_plan_id_ = 0;
  double last_planning_us_ = 0.0;
  double max_planning_us_ = 0.0;  // the longest job so far [us]
  std::int64_t proposal_period_cycles_ = 1;  ///< once a second: guidance.rate_hz cycles
  std::int64_t proposal_seq_ = 0;
  evade_cam_proposal_t proposal_msg_{};
  auth::KeyCmdResult key_cmd_last_result_ = auth::KeyCmdResult::kNone;

  // Authentication (docs/SECURITY.md).
  auth::KeyRing keys_;
  std::unique_ptr<auth::StateFile> state_file_;  // nullptr: memory only (tests)
  std::int16_t auth_required_mask_ = 0;
  VerifyBudget budget_;
  std::uint64_t auth_epoch_ = 0;       ///< +1 per change that must be on disk before it counts
  std::uint64_t persisted_epoch_ = 0;  ///< every change up to this epoch is on disk
  bool persist_failed_ = false;        ///< the last write failed: refuse what waits on it
  std::uint64_t failed_epoch_ = 0;     ///< the epoch that write would have put on disk
  std::int64_t persist_failures_ = 0;
  std::int32_t last_command_key_ = 0;

  // Telemetry: acknowledgements and the status, signed with the telemetry key.
  AckOutbox acks_;
  int callback_acks_left_ = kCallbackAcksPerCycle;
  std::int64_t ack_seq_ = 0;
  std::int64_t acks_published_ = 0;
  std::int64_t acks_unsent_ = 0;
  evade_cmd_ack_t last_ack_{};

  // Lockstep tick.
  bool tick_pending_ = false;
  std::int64_t tick_utime_ = 0;
  std::int64_t ticks_received_ = 0;
  std::int64_t ticks_missed_ = 0;

  // Outputs, preallocated.
  std::int64_t cmd_seq_ = 0;
  std::int64_t status_seq_ = 0;
  evade_thrust_cmd_t cmd_msg_{};
  evade_guidance_status_t status_msg_{};
  RawPublisher<evade_thrust_cmd_t> cmd_pub_;
  SigningPublisher<evade_guidance_status_t> status_pub_;
  SigningPublisher<evade_cmd_ack_t> ack_pub_;
  SigningPublisher<evade_cam_proposal_t> proposal_pub_;
};

}  // namespace evade::guidance_lcm::internal
