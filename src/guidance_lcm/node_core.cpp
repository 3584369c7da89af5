// Guidance node cycle (docs/GUIDANCE_NODE.md). The law is paper 000's −e_θ evasion
// (guidance_law.hpp); this file only moves data to and from it and guards the edge.
#include "evade/guidance_lcm/internal/node_core.hpp"

#include <time.h>

#include <cmath>
#include <stdexcept>

#include "evade/guidance_lcm/burn_plan_convert.hpp"
#include "evade/guidance_lcm/channels.hpp"
#include "evade/guidance_lcm/convert.hpp"
#include "evade/guidance_lcm/node_params.hpp"
#include "evade/guidance_lcm/validate.hpp"

namespace evade::guidance_lcm {
namespace {

std::int64_t monotonic_us() noexcept {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000 + ts.tv_nsec / 1000;
}

std::int8_t auth_mask(const AuthPolicy& p) noexcept {
  using S = evade_guidance_status_t;
  int m = S::AUTH_KEY_CMD;  // always required
  if (p.plan_required) m |= S::AUTH_PLAN;
  if (p.arm_required) m |= S::AUTH_ARM;
  if (p.nav_required) m |= S::AUTH_NAV;
  if (p.angles_required) m |= S::AUTH_ANGLES;
  if (p.clock_required) m |= S::AUTH_CLOCK;
  return static_cast<std::int8_t>(m);  // six bits: fits in int8
}

}  // namespace

static NodeConfig checked(const NodeConfig& cfg) {  // copied into cfg_ at construction
  const std::string err = cfg.validate();
  if (!err.empty()) throw std::invalid_argument(err);
  return cfg;
}

GuidanceNode::GuidanceNode(lcm_t* lcm, const NodeConfig& cfg, lcm_t* out_lcm,
                           const NodeSecurity& sec)
    : lcm_(lcm),
      cfg_(checked(cfg)),
      law_(cfg.guidance),
      stale_us_(static_cast<std::int64_t>(std::llround(cfg.guidance.stale_limit_s * 1e6))),
      future_us_(static_cast<std::int64_t>(std::llround(cfg.future_tolerance_s * 1e6))),
      queue_(static_cast<std::size_t>(cfg.queue_capacity)),
      seq_{SeqTracker(cfg.max_seq_jump), SeqTracker(cfg.max_seq_jump),
           SeqTracker(cfg.max_seq_jump)},
      armed_(cfg.guidance.armed),
      plan_exec_(guidance::PlanExecutorConfig::from(cfg.guidance)),
      keys_(sec.keys),
      state_file_(sec.state_path),
      cmd_pub_(out_lcm != nullptr ? out_lcm : lcm, kChanCmd),
      status_pub_(out_lcm != nullptr ? out_lcm : lcm, kChanStatus) {
  if (lcm_ == nullptr) throw std::invalid_argument("GuidanceNode: lcm is null");
  state_file_.load(&keys_);
  keys_.raise_sensor_floor(sec.sensor_arsn_floor_us);
  keys_.mark_persisted();
  auth_required_mask_ = auth_mask(cfg_.auth);
  verify_budget_left_ = cfg_.auth.max_verify_per_cycle;
  const char* names[kInCount] = {kChanAngles, kChanNav, kChanArm};
  for (std::size_t c = 0; c < kInArm; ++c) {
    ctx_[c] = SubContext{this, static_cast<int>(c)};  // c < kInCount: fits in int
    subs_[c] = subscribe(names[c], &GuidanceNode::on_input, &ctx_[c], true);
  }
  if (cfg_.lockstep) clock_sub_ = subscribe(kChanClock, &GuidanceNode::on_clock, this, true);
  const char* cmd_names[kCmdCount] = {kChanPlan, kChanArm, kChanKeyCmd};
  for (std::size_t c = 0; c < cmd_ctx_.size(); ++c) {
    cmd_ctx_[c] = SubContext{this, static_cast<int>(c)};  // c < kCmdCount: fits in int
    cmd_subs_[c] = subscribe(cmd_names[c], &GuidanceNode::on_command, &cmd_ctx_[c], true);
  }
  input_.armed = armed_;
}

GuidanceNode::~GuidanceNode() { unsubscribe_all(); }

// A refused subscription undoes the ones already made before the constructor throws: the
// destructor does not run for a node that failed to construct, and LCM would otherwise keep
// calling back into it.
// deep_queue: LCM's own per-subscription queue (udpm default 30) would drop bursts silently
// before our accounting sees them; every input and command channel gets a large one, so that
// the bounded queues that drop and count are ours (a flood of 20,000 plans per second is
// counted message by message: docs/SECURITY.md AUTH-5). Refused like a subscription when LCM refuses it.
lcm_subscription_t* GuidanceNode::subscribe(const char* channel, lcm_msg_handler_t handler,
                                            void* user, bool deep_queue) {
  lcm_subscription_t* s = lcm_subscribe(lcm_, channel, handler, user);
  const bool queue_ok = s == nullptr || !deep_queue ||
                        lcm_subscription_set_queue_capacity(s, 10000) == 0;
  if (s != nullptr && queue_ok) return s;
  if (s != nullptr) (void)lcm_unsubscribe(lcm_, s);  // failing already: its result adds nothing
  unsubscribe_all();
  throw std::runtime_error(std::string(s == nullptr ? "GuidanceNode: cannot subscribe to "
                                                    : "GuidanceNode: cannot size the LCM queue of ") +
                           channel);
}

// Teardown: a subscription LCM fails to remove leaves nothing the node could do about it,
// so lcm_unsubscribe's result is discarded.
void GuidanceNode::unsubscribe_all() noexcept {
  for (auto*& s : subs_) {
    if (s != nullptr) (void)lcm_unsubscribe(lcm_, s);
    s = nullptr;
  }
  for (auto*& s : cmd_subs_) {
    if (s != nullptr) (void)lcm_unsubscribe(lcm_, s);
    s = nullptr;
  }
  if (clock_sub_ != nullptr) (void)lcm_unsubscribe(lcm_, clock_sub_);
  clock_sub_ = nullptr;
}

void GuidanceNode::on_input(const lcm_recv_buf_t* rbuf, const char*, void* user) noexcept {
  auto* ctx = static_cast<SubContext*>(user);
  GuidanceNode* self = ctx->node;
  ++self->counts_.received;
  if (rbuf->data_size > kMaxInputBytes) {  // no input type is this large: corrupt
    self->counts_.add(Verdict::kRejected, Reason::kOversize);
    return;
  }
  const bool angles = ctx->channel == kInAngles;
  const std::int8_t bit = angles ? evade_guidance_status_t::AUTH_ANGLES : evade_guidance_status_t::AUTH_NAV;
  if ((self->auth_required_mask_ & bit) != 0 &&
      !self->authenticate(angles ? auth::ArsnSlot::kAngles : auth::ArsnSlot::kNav,
                          angles ? kChanAngles : kChanNav, rbuf)) {
    return;
  }
  int dropped_channel = -1;
  if (!self->queue_.push(ctx->channel, rbuf->data, rbuf->data_size, &dropped_channel)) {
    self->counts_.add(Verdict::kDropped);  // the oldest queued message made room
    if (dropped_channel >= 0 && dropped_channel < kInCount) {
      ++self->dropped_since_accept_[static_cast<std::size_t>(dropped_channel)];
    }
  }
}

void GuidanceNode::on_clock(const lcm_recv_buf_t* rbuf, const char*, void* user) noexcept {
  auto* self = static_cast<GuidanceNode*>(user);
  if ((self->auth_required_mask_ & evade_guidance_status_t::AUTH_CLOCK) != 0 &&
      !self->authenticate(auth::ArsnSlot::kClock, kChanClock, rbuf)) {
    return;  // counted; not a tick
  }
  evade_sim_clock_t tick{};
  if (tick.decode(rbuf->data, 0, static_cast<int>(rbuf->data_size)) !=
          static_cast<int>(rbuf->data_size) ||
      validate(tick) != Reason::kOk) {
    return;  // not a tick; the simulator will time out and say so
  }
  std::int64_t gaps = 0;
  if (self->tick_seq_.check(tick.seq, tick.utime, &gaps) != Reason::kOk) return;  // replayed
  ++self->ticks_received_;
  if (self->tick_pending_) ++self->ticks_missed_;  // previous tick never got its cycle
  self->tick_pending_ = true;
  self->tick_utime_ = tick.utime;
}

int GuidanceNode::drain() noexcept {
  int n = 0;
  while (n < cfg_.max_drain_per_cycle) {
    const int rc = lcm_handle_timeout(lcm_, 0);
    if (rc < 0) return -1;
    if (rc == 0) break;
    ++n;
  }
  return n;
}

int GuidanceNode::wait_for_tick(int timeout_ms, std::int64_t* tick_utime) noexcept {
  const std::int64_t deadline = monotonic_us() + static_cast<std::int64_t>(timeout_ms) * 1000;
  while (!tick_pending_) {
    const std::int64_t left_us = deadline - monotonic_us();
    if (left_us <= 0) return 0;
    const int rc = lcm_handle_timeout(lcm_, static_cast<int>((left_us + 999) / 1000));
    if (rc < 0) return -1;
  }
  tick_pending_ = false;
  *tick_utime = tick_utime_;
  return 1;
}

template <typename Msg>
bool GuidanceNode::admit(int channel, const std::uint8_t* data, std::uint32_t size,
                         std::int64_t now_us, Msg* msg) noexcept {
  const int n = msg->decode(data, 0, static_cast<int>(size));
  if (n < 0 || n != static_cast<int>(size)) {  // wrong type, truncated or trailing bytes
    counts_.add(Verdict::kRejected, Reason::kDecodeFailed);
    return false;
  }
  const Reason r = validate(*msg);
  if (r != Reason::kOk) {
    counts_.add(Verdict::kRejected, r);
    return false;
  }
  if (msg->utime > now_us + future_us_) {
    counts_.add(Verdict::kRejected, Reason::kFromFuture);
    return false;
  }
  if (msg->utime < now_us - stale_us_) {
    counts_.add(Verdict::kStale, Reason::kStaleUtime);
    return false;
  }
  std::int64_t gaps = 0;
  SeqTracker& tracker = seq_[static_cast<std::size_t>(channel)];
  const std::int64_t restarts = tracker.restarts();
  const Reason s = tracker.check(msg->seq, msg->utime, &gaps);
  if (s != Reason::kOk) {
    counts_.add(s == Reason::kSeqJump ? Verdict::kRejected : Verdict::kStale, s);
    return false;
  }
  // Gaps are numbers never received: the ones this node dropped from its own queue were.
  std::int64_t& dropped = dropped_since_accept_[static_cast<std::size_t>(channel)];
  counts_.seq_gaps += gaps > dropped ? gaps - dropped : 0;
  dropped = 0;
  counts_.seq_restarts += tracker.restarts() - restarts;
  return true;
}

// The arm command is admitted from the command inbox (node_commands.cpp).
template bool GuidanceNode::admit<evade_arm_t>(int, const std::uint8_t*, std::uint32_t,
                                               std::int64_t, evade_arm_t*) noexcept;

void GuidanceNode::process_queue(std::int64_t now_us) noexcept {
  have_cand_.fill(false);
  while (!queue_.empty()) {
    const RawMessage& raw = queue_.front();
    switch (raw.channel) {
      case kInAngles: {
        evade_angles_t m{};
        if (admit(raw.channel, raw.data.data(), raw.size, now_us, &m)) {
          if (have_cand_[kInAngles]) counts_.add(Verdict::kSuperseded);
          cand_angles_ = m;
          have_cand_[kInAngles] = true;
        }
        break;
      }
      case kInNav: {
        evade_nav_state_t m{};
        if (admit(raw.channel, raw.data.data(), raw.size, now_us, &m)) {
          if (have_cand_[kInNav]) counts_.add(Verdict::kSuperseded);
          cand_nav_ = m;
          have_cand_[kInNav] = true;
        }
        break;
      }
      default:
        counts_.add(Verdict::kRejected, Reason::kDecodeFailed);
        break;
    }
    queue_.pop();
  }
  input_.has_measurement = false;
  if (have_cand_[kInAngles]) {
    counts_.add(Verdict::kConsumed);
    from_lcm(cand_angles_, &input_.meas);
    input_.has_measurement = true;
    if (cand_angles_.valid) {
      have_angles_ = true;
      last_angles_utime_ = cand_angles_.utime;
    }
  }
  if (have_cand_[kInNav]) {
    counts_.add(Verdict::kConsumed);
    from_lcm(cand_nav_, &input_.nav);
  }
  input_.armed = armed_;
}

const evade_thrust_cmd_t& GuidanceNode::run_cycle(std::int64_t now_us) noexcept {
  process_queue(now_us);
  process_commands(now_us);
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

  if (cycles_ % cfg_.status_divider == 0) fill_status(now_us);
  verify_budget_left_ = cfg_.auth.max_verify_per_cycle;  // the next drain's budget
  return cmd_msg_;
}

}  // namespace evade::guidance_lcm
