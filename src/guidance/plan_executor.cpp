// Burn-plan executor (plan_executor.hpp; docs/GUIDANCE_NODE.md PLAN-*): validation on load,
// then one finite burn per impulse at the thrust limit, centred on its planned time.
#include "evade/guidance/plan_executor.hpp"

#include <cmath>

namespace evade::guidance {
namespace {

constexpr int kMax = BurnPlan::kMaxImpulses;

bool finite_plan(const BurnPlan& p) noexcept {
  for (int i = 0; i < p.n_impulses; ++i) {
    const ImpulsiveBurn& b = p.impulses[static_cast<std::size_t>(i)];
    if (!std::isfinite(b.t_s) || !b.dv_rsw_mps.allFinite()) return false;
    if (b.dv_eci_valid && !b.dv_eci_mps.allFinite()) return false;
  }
  return true;
}

bool frame_ok(const UplinkedPlan& p) noexcept {
  if (p.frame == PlanFrame::kRsw) return true;
  if (p.frame != PlanFrame::kEci) return false;
  for (int i = 0; i < p.plan.n_impulses; ++i)
    if (!p.plan.impulses[static_cast<std::size_t>(i)].dv_eci_valid) return false;
  return true;
}

// The Δv the executor flies, in the plan's frame.
Vec3 dv_of(const UplinkedPlan& p, int i) noexcept {
  const ImpulsiveBurn& b = p.plan.impulses[static_cast<std::size_t>(i)];
  return p.frame == PlanFrame::kEci ? b.dv_eci_mps : b.dv_rsw_mps;
}

// Whole cycles of a burn of |Δv| = mag at the thrust limit (at least one), as a double: a
// finite but huge Δv (1e300 m/s) has no int cycle count, so check_burns compares this with
// the burn-time limit before burn_of converts it.
// The (1 - 1e-12) keeps an exact multiple (0.5 m/s at 1 m/s^2 and 20 ms: 25 cycles) from
// rounding up to one cycle more; when it rounds down instead, |Δv| / (n T) would exceed the
// thrust limit by up to 1e-12 relative, so such an n gets one cycle more (fuzz finding 8).
double burn_cycles(const PlanExecutorConfig& c, double mag) noexcept {
  double n = std::ceil(mag / (c.max_accel_mps2 * c.cycle_s) * (1.0 - 1e-12));
  if (n < 1.0) n = 1.0;
  if (mag / (n * c.cycle_s) > c.max_accel_mps2) n += 1.0;
  return n;
}

// Plan epochs beyond ±1e18 µs (±31,700 years) are refused with the times beyond the exact µs
// range: burn times, windows and cycle times stay far from int64 overflow.
constexpr std::int64_t kMaxEpochAbsUs = 1000000000000000000;

// Unit vector along a finite, nonzero v. Dividing by the largest |component| first gives a
// vector whose largest entry is exactly ±1, so its norm is computed at full precision even
// when v is subnormal (stableNormalized alone rounds the norm of a 1e-320 m/s Δv to the few
// bits a subnormal holds and returns a direction off unit by 2e-4: fuzz finding 7).
Vec3 unit_direction(const Vec3& v) noexcept {
  const double scale = v.cwiseAbs().maxCoeff();
  const Vec3 w = v / scale;
  return w / w.norm();
}

// RSW → ECI rotation of the own orbit (columns R, S, W); false if nav cannot define it.
bool rsw_to_eci(const NavState& nav, Mat3* m) noexcept {
  if (!nav.valid || !nav.r_eci_m.allFinite() || !nav.v_eci_mps.allFinite()) return false;
  const Vec3 h = nav.r_eci_m.cross(nav.v_eci_mps);
  if (!(h.norm() > 0.0)) return false;
  const Vec3 r_hat = nav.r_eci_m.normalized();
  const Vec3 w_hat = h.normalized();
  m->col(0) = r_hat;
  m->col(1) = w_hat.cross(r_hat);
  m->col(2) = w_hat;
  return true;
}

}  // namespace

const char* plan_reject_name(PlanReject r) noexcept {
  switch (r) {
    case PlanReject::kNone: return "NONE";
    case PlanReject::kMalformed: return "MALFORMED";
    case PlanReject::kImpulseCount: return "IMPULSE_COUNT";
    case PlanReject::kNotFinite: return "NOT_FINITE";
    case PlanReject::kUnknownFrame: return "UNKNOWN_FRAME";
    case PlanReject::kBurnInPast: return "BURN_IN_PAST";
    case PlanReject::kNotOrdered: return "NOT_ORDERED";
    case PlanReject::kOverlapping: return "OVERLAPPING";
    case PlanReject::kOverBudget: return "OVER_BUDGET";
    case PlanReject::kOverThrustLimit: return "OVER_THRUST_LIMIT";
    case PlanReject::kNotNewer: return "NOT_NEWER";
    case PlanReject::kDisarmed: return "DISARMED";
    case PlanReject::kCount: break;
  }
  return "UNKNOWN";
}

const char* plan_end_name(PlanEnd e) noexcept {
  switch (e) {
    case PlanEnd::kNone: return "NONE";
    case PlanEnd::kCompleted: return "COMPLETED";
    case PlanEnd::kCancelledDisarm: return "CANCELLED_DISARM";
    case PlanEnd::kPreemptedEvasion: return "PREEMPTED_EVASION";
    case PlanEnd::kAbandonedSafe: return "ABANDONED_SAFE";
    case PlanEnd::kMissedStart: return "MISSED_START";
    case PlanEnd::kSuperseded: return "SUPERSEDED";
    case PlanEnd::kCancelledOnboard: return "CANCELLED_ONBOARD";
  }
  return "UNKNOWN";
}

PlanExecutorConfig PlanExecutorConfig::from(const GuidanceConfig& g) noexcept {
  PlanExecutorConfig c;
  c.max_accel_mps2 = g.max_accel_mps2;
  c.cycle_s = g.cycle_s();
  c.dv_budget_mps = g.dv_budget_mps;
  c.max_burn_s = g.max_burn_s;
  return c;
}

PlanExecutor::PlanExecutor(const PlanExecutorConfig& cfg) noexcept
    : cfg_(cfg), cycle_us_(std::llround(cfg.cycle_s * 1e6)) {}

// N whole cycles at a = |Δv| / (N T) ≤ a_max; the first cycle that may start it is
// T/2 before the start of the centred window [t_i − N T/2, t_i + N T/2].
PlanExecutor::Burn PlanExecutor::burn_of(const UplinkedPlan& p, int i) const noexcept {
  const Vec3 dv = dv_of(p, i);
  // stableNorm scales by the largest component first: a |dv| whose squares underflow
  // (components near 1e-160 m/s and below) is not rounded to zero.
  const double mag = dv.stableNorm();
  Burn b;
  b.cycles = static_cast<int>(burn_cycles(cfg_, mag));  // check_burns bounded it
  b.accel_mps2 = mag / (b.cycles * cfg_.cycle_s);
  b.dir = mag > 0.0 ? unit_direction(dv) : Vec3::Zero();
  const double t_us = p.plan.impulses[static_cast<std::size_t>(i)].t_s * 1e6;
  const double half_us = 0.5 * static_cast<double>((b.cycles + 1) * cycle_us_);
  b.first_cycle_us = p.epoch_utime_us + std::llround(t_us - half_us);
  return b;
}

// Timing and limits of the burns (the plan is finite, in a known frame, 1..8 impulses).
PlanReject PlanExecutor::check_burns(const UplinkedPlan& p, std::int64_t now_us) const noexcept {
  if (p.epoch_utime_us > kMaxEpochAbsUs || p.epoch_utime_us < -kMaxEpochAbsUs)
    return PlanReject::kNotFinite;
  for (int i = 0; i < p.plan.n_impulses; ++i) {
    const double t_s = p.plan.impulses[static_cast<std::size_t>(i)].t_s;
    if (std::abs(t_s) > 1e9) return PlanReject::kNotFinite;  // beyond the exact µs range
    if (!(burn_cycles(cfg_, dv_of(p, i).norm()) * cfg_.cycle_s <= cfg_.max_burn_s))
      return PlanReject::kOverThrustLimit;
    const Burn b = burn_of(p, i);
    if (b.first_cycle_us <= now_us) return PlanReject::kBurnInPast;
    if (i > 0) {
      if (!(t_s > p.plan.impulses[static_cast<std::size_t>(i - 1)].t_s))
        return PlanReject::kNotOrdered;
      const Burn a = burn_of(p, i - 1);
      if (b.first_cycle_us < a.first_cycle_us + (a.cycles + 1) * cycle_us_)
        return PlanReject::kOverlapping;
    }
  }
  return PlanReject::kNone;
}

PlanReject PlanExecutor::check(const UplinkedPlan& p, std::int64_t now_us, bool armed,
                               double dv_used_mps) const noexcept {
  if (p.plan.n_impulses < 1 || p.plan.n_impulses > kMax) return PlanReject::kImpulseCount;
  if (!finite_plan(p.plan)) return PlanReject::kNotFinite;
  if (!frame_ok(p)) return PlanReject::kUnknownFrame;
  if (!armed) return PlanReject::kDisarmed;
  if (have_last_id_ && p.plan.plan_id <= last_id_) return PlanReject::kNotNewer;
  const PlanReject r = check_burns(p, now_us);
  if (r != PlanReject::kNone) return r;
  double total_mps = 0.0;
  for (int i = 0; i < p.plan.n_impulses; ++i) total_mps += dv_of(p, i).norm();
  if (!std::isfinite(dv_used_mps) ||
      total_mps > cfg_.dv_budget_mps - status_.dv_total_mps - dv_used_mps)
    return PlanReject::kOverBudget;
  return PlanReject::kNone;
}

void PlanExecutor::count_rejection(PlanReject r) noexcept {
  if (r == PlanReject::kNone || r >= PlanReject::kCount) r = PlanReject::kMalformed;
  ++status_.rejected[static_cast<std::size_t>(r)];
  status_.last_reject = r;
}

PlanReject PlanExecutor::load(const UplinkedPlan& p, std::int64_t now_us, bool armed,
                              double dv_used_mps) noexcept {
  const PlanReject r = check(p, now_us, armed, dv_used_mps);
  if (r != PlanReject::kNone) {
    count_rejection(r);
    return r;
  }
  if (active()) {
    account(now_us);
    cancel(PlanEnd::kSuperseded);
  }
  frame_ = p.frame;
  for (int i = 0; i < p.plan.n_impulses; ++i) burns_[static_cast<std::size_t>(i)] = burn_of(p, i);
  have_last_id_ = true;
  last_id_ = p.plan.plan_id;
  const double dv_total = status_.dv_total_mps;
  const auto rejected = status_.rejected;
  const PlanReject last_reject = status_.last_reject;
  const std::int64_t accepted = status_.accepted + 1;
  status_ = PlanExecStatus{};
  status_.plan_id = p.plan.plan_id;
  status_.state = PlanState::kWaiting;
  status_.n_impulses = p.plan.n_impulses;
  status_.dv_total_mps = dv_total;
  status_.rejected = rejected;
  status_.last_reject = last_reject;
  status_.accepted = accepted;
  current_ = 0;
  cycles_left_ = 0;
  prev_accel_mps2_ = 0.0;
  return PlanReject::kNone;
}

void PlanExecutor::cancel(PlanEnd why) noexcept {
  if (!active()) return;
  if (status_.state == PlanState::kBurning)
    status_.burn_end_us[static_cast<std::size_t>(current_)] = prev_us_;
  status_.state = PlanState::kEnded;
  status_.end = why;
  prev_accel_mps2_ = 0.0;
  cycles_left_ = 0;
}

// Δv of the thrust commanded at the previous step, over the time it was in force; closes a
// burn whose cycles have all been flown.
void PlanExecutor::account(std::int64_t now_us) noexcept {
  if (status_.state != PlanState::kBurning) return;
  const auto i = static_cast<std::size_t>(current_);
  if (prev_accel_mps2_ > 0.0 && now_us > prev_us_) {
    const double dv = prev_accel_mps2_ * 1e-6 * static_cast<double>(now_us - prev_us_);
    status_.dv_delivered_mps[i] += dv;
    status_.dv_total_mps += dv;
  }
  prev_accel_mps2_ = 0.0;
  prev_us_ = now_us;
  if (cycles_left_ > 0) return;
  status_.burn_end_us[i] = now_us;
  ++status_.impulses_done;
  ++current_;
  const bool done = current_ >= status_.n_impulses;
  status_.state = done ? PlanState::kEnded : PlanState::kWaiting;
  if (done) status_.end = PlanEnd::kCompleted;
}

PlanThrust PlanExecutor::thrust(const NavState& nav) const noexcept {
  const Burn& b = burns_[static_cast<std::size_t>(current_)];
  PlanThrust t;
  if (!(b.accel_mps2 > 0.0)) return t;
  Mat3 m = Mat3::Identity();
  if (frame_ == PlanFrame::kRsw && !rsw_to_eci(nav, &m)) return t;
  t.u_eci = m * b.dir;
  t.accel_mps2 = b.accel_mps2;
  return t;
}

// Waiting: start the burn at its first cycle (SAFE or no usable nav then: abandoned; the
// cycle already passed: missed). Burning: one more cycle unless the law is SAFE.
PlanThrust PlanExecutor::next_burn(const NavState& nav, GuidanceMode law_mode,
                                   std::int64_t now_us) noexcept {
  Mat3 m;
  const bool nav_ok = frame_ == PlanFrame::kEci || rsw_to_eci(nav, &m);
  const auto i = static_cast<std::size_t>(current_);
  if (status_.state == PlanState::kWaiting) {
    const Burn& b = burns_[i];
    if (now_us < b.first_cycle_us) return PlanThrust{};
    if (now_us >= b.first_cycle_us + cycle_us_) {
      cancel(PlanEnd::kMissedStart);
      return PlanThrust{};
    }
    if (law_mode == GuidanceMode::kSafe || !nav_ok) {
      cancel(PlanEnd::kAbandonedSafe);
      return PlanThrust{};
    }
    status_.state = PlanState::kBurning;
    status_.burn_start_us[i] = now_us;
    cycles_left_ = b.cycles;
  } else if (law_mode == GuidanceMode::kSafe || !nav_ok) {
    cancel(PlanEnd::kAbandonedSafe);
    return PlanThrust{};
  }
  --cycles_left_;
  PlanThrust t = thrust(nav);  // not const: returned by (automatic) move
  prev_accel_mps2_ = t.accel_mps2;
  prev_us_ = now_us;
  return t;
}

PlanThrust PlanExecutor::step(const NavState& nav, bool armed, GuidanceMode law_mode,
                              std::int64_t now_us) noexcept {
  account(now_us);
  if (!active()) return PlanThrust{};
  if (!armed) {
    cancel(PlanEnd::kCancelledDisarm);
    return PlanThrust{};
  }
  if (law_mode == GuidanceMode::kEvade) {
    cancel(PlanEnd::kPreemptedEvasion);
    return PlanThrust{};
  }
  return next_burn(nav, law_mode, now_us);
}

ThrustCommand merge_plan_thrust(const ThrustCommand& law_cmd, const PlanThrust& plan) noexcept {
  if (!(plan.accel_mps2 > 0.0) || law_cmd.accel_mps2 > 0.0) return law_cmd;
  ThrustCommand c = law_cmd;
  c.u_eci = plan.u_eci;
  c.accel_mps2 = plan.accel_mps2;
  return c;
}

}  // namespace evade::guidance
