// Fuzz harness: guidance::PlanExecutor's validation and execution of an uplinked burn plan
// (docs/GUIDANCE_NODE.md PLAN-VAL-1, PLAN-EXE-1), fed directly (no LCM, so the fields take
// any value the struct can hold: NaN, Inf, huge times and Δv, any epoch, any frame code).
// Input: now [µs], armed, Δv already used, plan id, epoch [µs], frame code, n_impulses, then
// per impulse t [s], Δv RSW, ECI flag, Δv ECI (byte_reader.hpp: raw little-endian).
// Checked: a rejection is counted under its reason and leaves no active plan; an accepted
// plan satisfies PLAN-VAL-1 (armed, 1..8 impulses, finite, |t| <= 1e9 s, strictly ordered,
// total |Δv| within the budget not yet spent); executing it over regular cycles (at most
// kMaxSteps) thrusts only with a unit direction at 0 < a <= a_max, and delivers no more than
// each impulse's |Δv| (to rounding), never more than the budget in total.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "byte_reader.hpp"
#include "evade/guidance/plan_executor.hpp"
#include "fuzz_check.hpp"

namespace {

using evade::guidance::PlanExecutor;
using evade::guidance::PlanReject;

constexpr int kMaxSteps = 4000;

evade::guidance::UplinkedPlan read_plan(evade::fuzz::ByteReader& in) {
  evade::guidance::UplinkedPlan p;
  p.plan.plan_id = in.get<std::int64_t>();
  p.epoch_utime_us = in.get<std::int64_t>();
  p.frame = static_cast<evade::guidance::PlanFrame>(in.get<std::uint8_t>() % 4);
  p.plan.n_impulses = static_cast<int>(in.get<std::int8_t>());
  for (auto& b : p.plan.impulses) {
    b.t_s = in.get<double>();
    for (int k = 0; k < 3; ++k) b.dv_rsw_mps[k] = in.get<double>();
    b.dv_eci_valid = in.flag();
    for (int k = 0; k < 3; ++k) b.dv_eci_mps[k] = in.get<double>();
  }
  return p;
}

double dv_norm(const evade::guidance::UplinkedPlan& p, int i) {
  const auto& b = p.plan.impulses[static_cast<std::size_t>(i)];
  return (p.frame == evade::guidance::PlanFrame::kEci ? b.dv_eci_mps : b.dv_rsw_mps).norm();
}

void check_accepted(const evade::guidance::UplinkedPlan& p, bool armed, double budget_left) {
  EVADE_FUZZ_CHECK(armed, "accepted only when armed");
  EVADE_FUZZ_CHECK(p.plan.n_impulses >= 1 && p.plan.n_impulses <= evade::BurnPlan::kMaxImpulses,
                   "accepted with 1..8 impulses");
  double total = 0.0;
  for (int i = 0; i < p.plan.n_impulses; ++i) {
    const auto& b = p.plan.impulses[static_cast<std::size_t>(i)];
    EVADE_FUZZ_CHECK(std::isfinite(b.t_s) && std::fabs(b.t_s) <= 1e9, "accepted times finite");
    EVADE_FUZZ_CHECK(std::isfinite(dv_norm(p, i)), "accepted dv finite");
    if (i > 0)
      EVADE_FUZZ_CHECK(b.t_s > p.plan.impulses[static_cast<std::size_t>(i - 1)].t_s,
                       "accepted times strictly increasing");
    total += dv_norm(p, i);
  }
  EVADE_FUZZ_CHECK(total <= budget_left, "accepted plan within the budget not yet spent");
}

void fly(PlanExecutor& ex, const evade::guidance::UplinkedPlan& p, std::int64_t now_us,
         const evade::guidance::PlanExecutorConfig& cfg, bool accepted) {
  evade::guidance::NavState nav;
  nav.valid = true;
  nav.r_eci_m = evade::Vec3(7.0e6, 0.0, 0.0);
  nav.v_eci_mps = evade::Vec3(0.0, 7546.0, 0.0);
  const auto cycle_us = static_cast<std::int64_t>(std::llround(cfg.cycle_s * 1e6));
  // Start just before the first burn's window when that is near, so bursts are flown.
  std::int64_t t = now_us;
  for (int k = 0; k < kMaxSteps; ++k) {
    if (t > INT64_MAX - cycle_us) break;
    t += cycle_us;
    const evade::guidance::PlanThrust th =
        ex.step(nav, true, evade::guidance::GuidanceMode::kStandby, t);
    EVADE_FUZZ_CHECK(std::isfinite(th.accel_mps2) && th.accel_mps2 >= 0.0 &&
                         th.accel_mps2 <= cfg.max_accel_mps2,
                     "plan thrust within [0, max_accel]");
    if (th.accel_mps2 > 0.0) {
      EVADE_FUZZ_CHECK(accepted, "no thrust without an accepted plan");
      EVADE_FUZZ_CHECK(std::fabs(th.u_eci.norm() - 1.0) <= 1e-9, "unit plan thrust direction");
    }
  }
  const evade::guidance::PlanExecStatus& s = ex.status();
  for (int i = 0; i < s.n_impulses && accepted; ++i) {
    const double want = dv_norm(p, i);
    EVADE_FUZZ_CHECK(s.dv_delivered_mps[static_cast<std::size_t>(i)] <= want * (1.0 + 1e-9) + 1e-12,
                     "no impulse delivers more than its |dv|");
  }
  EVADE_FUZZ_CHECK(s.dv_total_mps <= cfg.dv_budget_mps * (1.0 + 1e-9), "total dv within budget");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  evade::fuzz::ByteReader in(data, size);
  const auto now_us = in.get<std::int64_t>();
  const bool armed = in.flag();
  const double dv_used = std::fabs(in.get<double>());  // the law's spent Δv: >= 0 or NaN
  const evade::guidance::UplinkedPlan p = read_plan(in);
  const evade::guidance::PlanExecutorConfig cfg;
  PlanExecutor ex(cfg);
  const PlanReject r = ex.load(p, now_us, armed, dv_used);
  const bool accepted = r == PlanReject::kNone;
  if (accepted) {
    check_accepted(p, armed, cfg.dv_budget_mps - dv_used);
    EVADE_FUZZ_CHECK(ex.active() && ex.status().accepted == 1, "accepted plan is active");
  } else {
    EVADE_FUZZ_CHECK(r < PlanReject::kCount, "reject reason in range");
    EVADE_FUZZ_CHECK(ex.status().rejected[static_cast<std::size_t>(r)] == 1 &&
                         ex.status().last_reject == r, "rejection counted under its reason");
    EVADE_FUZZ_CHECK(!ex.active(), "a rejected plan is not active");
  }
  fly(ex, p, now_us, cfg, accepted);
  return 0;
}
