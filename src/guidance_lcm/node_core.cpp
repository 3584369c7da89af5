// Guidance node cycle (docs/GUIDANCE_NODE.md). The law is paper 000's −e_θ evasion
// (guidance_law.hpp); this file only moves data to and from it: construction, the subscribe
// loop over the input table (node_inputs.hpp), draining, the lockstep wait and the cycle.
// Receiving is node_receive.cpp, the sensors node_sensors.cpp, the commands node_commands.cpp,
// the acknowledgements and the status node_telemetry.cpp.
#include "evade/guidance_lcm/internal/node_core.hpp"

#include <time.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "evade/guidance_lcm/channels.hpp"
#include "evade/guidance_lcm/convert.hpp"
#include "evade/guidance_lcm/internal/node_state.hpp"

namespace evade::guidance_lcm::internal {
namespace {

// The node reads its clocks through timespec: a 32-bit time_t would end in January 2038, within
// a spacecraft's life (cmake/toolchains/armhf-linux-gnu.cmake builds 32-bit ARM with
// _TIME_BITS=64; a toolchain file of your own must too).
static_assert(sizeof(time_t) >= 8, "evade's guidance node needs a 64-bit time_t (-D_TIME_BITS=64)");

std::int64_t monotonic_us() noexcept {
  timespec ts{};
  (void)clock_gettime(CLOCK_MONOTONIC, &ts);  // CLOCK_MONOTONIC always exists: cannot fail
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000 + ts.tv_nsec / 1000;
}

NodeConfig checked(const NodeConfig& cfg) {  // copied into cfg_ at construction
  const std::string err = cfg.validate();
  if (!err.empty()) throw std::invalid_argument(err);
  return cfg;
}

SeqTracker tracker(const NodeConfig& cfg) { return SeqTracker(cfg.max_seq_jump); }

}  // namespace

NodeCore::NodeCore(lcm_t* lcm, const NodeConfig& cfg, lcm_t* out_lcm, const NodeSecurity& sec)
    : lcm_(lcm),
      cfg_(checked(cfg)),
      law_(cfg.guidance),
      stale_us_(static_cast<std::int64_t>(std::llround(cfg.guidance.stale_limit_s * 1e6))),
      future_us_(static_cast<std::int64_t>(std::llround(cfg.future_tolerance_s * 1e6))),
      refill_window_us_(static_cast<std::int64_t>(std::llround(1e6 / cfg.guidance.rate_hz))),
      drain_us_(static_cast<std::int64_t>(std::llround(cfg.max_drain_s * 1e6))),
      queue_(static_cast<std::size_t>(cfg.queue_capacity)),
      seq_{tracker(cfg), tracker(cfg), tracker(cfg), tracker(cfg), tracker(cfg), tracker(cfg),
           tracker(cfg), tracker(cfg)},
      armed_(cfg.guidance.armed),
      plan_exec_(guidance::PlanExecutorConfig::from(cfg.guidance)),
      responder_(cfg_.autonomy),
      planner_(cfg_.response),
      proposal_period_cycles_(std::max<std::int64_t>(1, std::llround(cfg_.guidance.rate_hz))),
      keys_(sec.keys),
      auth_required_mask_(auth_required_mask(cfg_.auth)),
      budget_(cfg_.auth),
      cmd_pub_(out_lcm != nullptr ? out_lcm : lcm, kChanCmd),
      status_pub_(out_lcm != nullptr ? out_lcm : lcm, kChanStatus),
      ack_pub_(out_lcm != nullptr ? out_lcm : lcm, kChanCmdAck),
      proposal_pub_(out_lcm != nullptr ? out_lcm : lcm, kChanCamProposal) {
  if (lcm_ == nullptr) throw std::invalid_argument("GuidanceNode: lcm is null");
  state_file_ = start_auth_state(sec, &keys_);  // initialization: may throw, naming the file
  keys_.raise_sensor_floor(sec.sensor_arsn_floor_us);
  keys_.mark_persisted();
  if (const auth::KeyEntry* tm = keys_.telemetry_key()) {
    SigningKey k;
    k.id = tm->id;
    k.key = tm->key;
    status_pub_.set_signing_key(k);
    ack_pub_.set_signing_key(k);
    proposal_pub_.set_signing_key(k);
  }
  for (const InputRow& row : kInputRows) {
    if (row.kind == InputKind::kTick && !cfg_.lockstep) continue;  // ticks only in lockstep
    ctx_[index(row.input)] = SubContext{this, row.input};
    subs_[index(row.input)] = subscribe(row);
  }
  budget_.mark_refilled(monotonic_us());
  input_.armed = armed_;
}

NodeCore::~NodeCore() { unsubscribe_all(); }

// A refused subscription undoes the ones already made before the constructor throws: the
// destructor does not run for a node that failed to construct, and LCM would otherwise keep
// calling back into it.
// LCM's own per-subscription queue (udpm default 30) would drop bursts silently before our
// accounting sees them; every input gets a large one, so that the bounded queues that drop and
// count are ours (a flood of 20,000 plans per second is counted message by message:
// docs/SECURITY.md AUTH-5). Refused like a subscription when LCM refuses it.
lcm_subscription_t* NodeCore::subscribe(const InputRow& row) {
  lcm_subscription_t* s =
      lcm_subscribe(lcm_, row.channel, &NodeCore::on_message, &ctx_[index(row.input)]);
  const bool queue_ok = s == nullptr || lcm_subscription_set_queue_capacity(s, 10000) == 0;
  if (s != nullptr && queue_ok) return s;
  if (s != nullptr) (void)lcm_unsubscribe(lcm_, s);  // failing already: its result adds nothing
  unsubscribe_all();
  throw std::runtime_error(std::string(s == nullptr ? "GuidanceNode: cannot subscribe to "
                                                    : "GuidanceNode: cannot size the LCM queue of ") +
                           row.channel);
}

// Teardown: a subscription LCM fails to remove leaves nothing the node could do about it,
// so lcm_unsubscribe's result is discarded.
void NodeCore::unsubscribe_all() noexcept {
  for (auto*& s : subs_) {
    if (s != nullptr) (void)lcm_unsubscribe(lcm_, s);
    s = nullptr;
  }
}

// Bounded in count and in time (node.max_drain_per_cycle, node.max_drain_s): under a flood the
// cycle's input work stops there and the rest waits in LCM's queues for the next cycle.
int NodeCore::drain() noexcept {
  int n = 0;
  const std::int64_t deadline = monotonic_us() + drain_us_;
  while (n < cfg_.max_drain_per_cycle) {
    if (n % 16 == 15 && monotonic_us() >= deadline) break;  // the clock read every 16 messages
    const int rc = lcm_handle_timeout(lcm_, 0);
    if (rc < 0) return -1;
    if (rc == 0) break;
    ++n;
  }
  return n;
}

// The budgets refill every cycle period of waiting (VerifyBudget): a burst of forged messages
// between two ticks delays at most one window, it cannot wedge the node (issue 40, row 7).
int NodeCore::wait_for_tick(int timeout_ms, std::int64_t* tick_utime) noexcept {
  const std::int64_t deadline = monotonic_us() + static_cast<std::int64_t>(timeout_ms) * 1000;
  while (!tick_pending_) {
    const std::int64_t now = monotonic_us();
    const std::int64_t left_us = deadline - now;
    if (left_us <= 0) return 0;
    budget_.refill_after(now, refill_window_us_);
    const std::int64_t slice_us = left_us < refill_window_us_ ? left_us : refill_window_us_;
    const int rc = lcm_handle_timeout(lcm_, static_cast<int>((slice_us + 999) / 1000));
    if (rc < 0) return -1;
  }
  tick_pending_ = false;
  *tick_utime = tick_utime_;
  return 1;
}

const evade_thrust_cmd_t& NodeCore::run_cycle(std::int64_t now_us) noexcept {
  last_cycle_us_ = now_us;
  process_queue(now_us);
  process_commands(now_us);
  step_autonomy(now_us);  // the responder's one action of this cycle, before the executor steps
  input_.armed = armed_;
  // Watchdog (NODE-WD-1): the newest valid measurement received is older than the stale
  // limit. Its verdict is an input of the law, which then commands SAFE and counts it.
  const bool silent = have_angles_ && now_us - last_angles_utime_ > stale_us_;
  input_.watchdog = silent ? guidance::WatchdogVerdict::kInputSilent
                           : guidance::WatchdogVerdict::kAlive;
  guidance::ThrustCommand cmd = law_.step(input_, now_us);
  // Uplinked plan (PLAN-EXE-1): flies only when the law does not thrust (EVADE pre-empts it).
  cmd = guidance::merge_plan_thrust(cmd, plan_exec_.step(input_.nav, armed_, cmd.mode, now_us));
  cmd.utime_us = now_us;
  to_lcm(cmd, ++cmd_seq_, have_angles_ ? last_angles_utime_ : -1, &cmd_msg_);
  if (cmd_pub_.publish(cmd_msg_) != 0) ++publish_failures_;
  ++cycles_;
  publish_acks();
  publish_proposals(now_us);
  if (cycles_ % cfg_.status_divider == 0) fill_status(now_us);
  budget_.refill();  // the next drain's budgets
  budget_.mark_refilled(monotonic_us());
  callback_acks_left_ = kCallbackAcksPerCycle;
  return cmd_msg_;
}

int NodeCore::persist_auth_state() noexcept {
  if (state_file_ == nullptr) {
    persisted_epoch_ = auth_epoch_;
    return 0;
  }
  if (!keys_.dirty() && persisted_epoch_ == auth_epoch_) return 0;
  const std::uint64_t epoch = auth_epoch_;
  const int rc = state_file_->save(keys_);
  if (rc != 0) {
    ++persist_failures_;
    persist_failed_ = true;
    failed_epoch_ = epoch;
    return rc;
  }
  keys_.mark_persisted();
  persisted_epoch_ = epoch;
  return 0;
}

// NODE-IN-1 at shutdown: what is still queued or waiting is counted, never lost from the sums.
void NodeCore::stop() noexcept {
  while (!queue_.empty()) {
    counts_.add(Verdict::kDropped, Reason::kStopped);
    queue_.pop();
  }
  for (std::size_t i = 0; i < cmd_inbox_.size(); ++i) {
    CommandInbox::Slot& s = cmd_inbox_.at(i);
    if (s.stage != CommandInbox::Stage::kDone) counts_.add(Verdict::kDropped, Reason::kStopped);
    s.stage = CommandInbox::Stage::kDone;
  }
  cmd_inbox_.compact();
  tick_pending_ = false;
}

}  // namespace evade::guidance_lcm::internal
