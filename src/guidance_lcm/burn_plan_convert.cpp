// BurnPlan <-> evade_burn_plan_t (burn_plan_convert.hpp): the checks on either side, then a
// field-by-field copy.
#include "evade/guidance_lcm/burn_plan_convert.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace evade::guidance_lcm {
namespace {

using guidance::PlanFrame;
using guidance::PlanReject;

constexpr int kObservabilitySource = static_cast<int>(PlanSource::kObservability);
constexpr int kMax = BurnPlan::kMaxImpulses;
static_assert(kMax == evade_burn_plan_t::MAX_IMPULSES, "message capacity = BurnPlan's");
static_assert(static_cast<int>(PlanFrame::kRsw) == evade_burn_plan_t::FRAME_RSW, "frame code");
static_assert(static_cast<int>(PlanFrame::kEci) == evade_burn_plan_t::FRAME_ECI, "frame code");
static_assert(static_cast<int>(PlanSource::kCollisionAvoidance) ==
                  evade_burn_plan_t::SOURCE_COLLISION_AVOIDANCE, "source code");

bool known_source(int s) noexcept {
  return s == static_cast<int>(PlanSource::kUnknown) ||
         s == static_cast<int>(PlanSource::kThreatArea) ||
         s == static_cast<int>(PlanSource::kFormation) || s == kObservabilitySource ||
         s == static_cast<int>(PlanSource::kCollisionAvoidance);
}
bool known_objective(int k) noexcept {
  return k >= static_cast<int>(PlanObjective::kPaper) &&
         k <= static_cast<int>(PlanObjective::kEstimation);
}
bool all_finite3(const double* v) noexcept {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

[[noreturn]] void bad(const std::string& field, const std::string& what) {
  throw std::invalid_argument("BurnPlan." + field + " " + what);
}
std::string num(double x) {
  std::ostringstream os;
  os.precision(17);
  os << x;
  return os.str();
}
void require_finite(const std::string& field, double x) {
  if (!std::isfinite(x)) bad(field, "= " + num(x) + ": must be finite");
}
void require_finite(const std::string& field, const Vec3& v) {
  if (!v.allFinite())
    bad(field, "= [" + num(v.x()) + ", " + num(v.y()) + ", " + num(v.z()) + "]: must be finite");
}

void check_impulses(const BurnPlan& p, PlanFrame frame) {
  if (p.n_impulses < 1 || p.n_impulses > kMax)
    bad("n_impulses", "= " + std::to_string(p.n_impulses) + ": must be in [1, " +
                          std::to_string(kMax) + "]");
  for (int k = 0; k < p.n_impulses; ++k) {
    const ImpulsiveBurn& b = p.impulses[static_cast<std::size_t>(k)];
    const std::string at = "impulses[" + std::to_string(k) + "].";
    require_finite(at + "t_s", b.t_s);
    require_finite(at + "dv_rsw_mps", b.dv_rsw_mps);
    if (b.dv_eci_valid) require_finite(at + "dv_eci_mps", b.dv_eci_mps);
    if (frame == PlanFrame::kEci && !b.dv_eci_valid)
      bad(at + "dv_eci_valid", "= false: frame ECI needs every impulse's ECI delta-v");
  }
  if (frame != PlanFrame::kRsw && frame != PlanFrame::kEci)
    bad("frame", "= " + std::to_string(static_cast<int>(frame)) + ": allowed 0 RSW, 1 ECI");
}

void check_source(const BurnPlan& p) {
  if (!known_source(p.source))
    bad("source", "= " + std::to_string(p.source) +
                      ": unknown planner code (allowed: 0 unknown, 1 threat-area, 3 formation, "
                      "4 observability, 5 collision avoidance)");
  const ObservabilityPlanInfo& o = p.observability;
  if (o.valid != (p.source == kObservabilitySource))
    bad("observability.valid", std::string("= ") + (o.valid ? "true" : "false") +
                                   " does not match source = " + std::to_string(p.source) +
                                   " (the block is filled exactly when source = 4)");
  if (!o.valid) return;
  if (!known_objective(o.objective))
    bad("observability.objective", "= " + std::to_string(o.objective) +
                                       ": allowed 0 paper, 1 los-change, 2 estimation");
  require_finite("observability.eps_rad", o.eps_rad);
  require_finite("observability.theta_rad", o.theta_rad);
  require_finite("observability.objective_value", o.objective_value);
  if (o.evaluations < 0)
    bad("observability.evaluations", "= " + std::to_string(o.evaluations) + ": must be >= 0");
}

struct PlanVerdict {
  PlanReject reject;
  const char* why;
};

PlanVerdict impulses_verdict(const evade_burn_plan_t& m) noexcept {
  if (m.n_impulses < 1 || m.n_impulses > kMax)
    return {PlanReject::kImpulseCount, "evade_burn_plan_t.n_impulses: must be in [1, 8]"};
  for (int k = 0; k < m.n_impulses; ++k) {
    if (m.impulse_dv_eci_valid[k] != 0 && m.impulse_dv_eci_valid[k] != 1)
      return {PlanReject::kMalformed, "evade_burn_plan_t.impulse_dv_eci_valid: must be 0 or 1"};
    if (!std::isfinite(m.impulse_t_s[k]))
      return {PlanReject::kNotFinite, "evade_burn_plan_t.impulse_t_s: not finite"};
    if (!all_finite3(m.impulse_dv_rsw_mps[k]))
      return {PlanReject::kNotFinite, "evade_burn_plan_t.impulse_dv_rsw_mps: not finite"};
    if (m.impulse_dv_eci_valid[k] == 1 && !all_finite3(m.impulse_dv_eci_mps[k]))
      return {PlanReject::kNotFinite, "evade_burn_plan_t.impulse_dv_eci_mps: not finite"};
    if (!std::isfinite(m.impulse_dv_mps[k]))
      return {PlanReject::kNotFinite, "evade_burn_plan_t.impulse_dv_mps: not finite"};
    if (m.frame == evade_burn_plan_t::FRAME_ECI && m.impulse_dv_eci_valid[k] != 1)
      return {PlanReject::kUnknownFrame,
              "evade_burn_plan_t.frame: FRAME_ECI needs every impulse_dv_eci_valid = 1"};
  }
  if (m.frame != evade_burn_plan_t::FRAME_RSW && m.frame != evade_burn_plan_t::FRAME_ECI)
    return {PlanReject::kUnknownFrame, "evade_burn_plan_t.frame: allowed 0 RSW, 1 ECI"};
  return {PlanReject::kNone, nullptr};
}

PlanVerdict source_verdict(const evade_burn_plan_t& m) noexcept {
  if (!known_source(m.source))
    return {PlanReject::kMalformed,
            "evade_burn_plan_t.source: unknown planner code (allowed 0, 1, 3, 4, 5)"};
  if (m.source != kObservabilitySource) return {PlanReject::kNone, nullptr};
  if (!known_objective(m.objective))
    return {PlanReject::kMalformed,
            "evade_burn_plan_t.objective: allowed 0 paper, 1 los-change, 2 estimation"};
  if (!std::isfinite(m.eps_rad) || !std::isfinite(m.theta_rad))
    return {PlanReject::kNotFinite, "evade_burn_plan_t.eps_rad/theta_rad: not finite"};
  if (!std::isfinite(m.objective_value))
    return {PlanReject::kNotFinite, "evade_burn_plan_t.objective_value: not finite"};
  if (m.evaluations < 0)
    return {PlanReject::kMalformed, "evade_burn_plan_t.evaluations: must be >= 0"};
  return {PlanReject::kNone, nullptr};
}

PlanVerdict message_verdict(const evade_burn_plan_t& m) noexcept {
  const PlanVerdict v = impulses_verdict(m);
  return v.reject != PlanReject::kNone ? v : source_verdict(m);
}

void copy_impulses(const BurnPlan& plan, evade_burn_plan_t* m) {
  for (int k = 0; k < plan.n_impulses; ++k) {
    const ImpulsiveBurn& b = plan.impulses[static_cast<std::size_t>(k)];
    m->impulse_t_s[k] = b.t_s;
    for (int i = 0; i < 3; ++i) {
      m->impulse_dv_rsw_mps[k][i] = b.dv_rsw_mps(i);
      m->impulse_dv_eci_mps[k][i] = b.dv_eci_valid ? b.dv_eci_mps(i) : 0.0;
    }
    m->impulse_dv_eci_valid[k] = b.dv_eci_valid ? 1 : 0;
    m->impulse_dv_mps[k] = b.dv_rsw_mps.norm();
  }
}

}  // namespace

void to_lcm(const BurnPlan& plan, std::int64_t utime, std::int64_t seq, std::int64_t epoch_utime,
            guidance::PlanFrame frame, evade_burn_plan_t* out) {
  check_impulses(plan, frame);
  check_source(plan);
  const ObservabilityPlanInfo& o = plan.observability;
  evade_burn_plan_t m{};
  m.utime = utime;
  m.seq = seq;
  m.epoch_utime = epoch_utime;
  m.frame = static_cast<std::int8_t>(frame);
  m.n_impulses = static_cast<std::int8_t>(plan.n_impulses);
  copy_impulses(plan, &m);
  if (o.valid) {
    m.eps_rad = o.eps_rad;
    m.theta_rad = o.theta_rad;
    m.objective = static_cast<std::int8_t>(o.objective);
    m.objective_value = o.objective_value;
    m.evaluations = o.evaluations;
  }
  m.source = static_cast<std::int16_t>(plan.source);
  *out = m;
}

void to_lcm(const BurnPlan& plan, std::int64_t utime, std::int64_t seq, evade_burn_plan_t* out) {
  to_lcm(plan, utime, seq, utime, guidance::PlanFrame::kRsw, out);
}

const char* burn_plan_message_error(const evade_burn_plan_t& m) noexcept {
  return message_verdict(m).why;
}

guidance::PlanReject burn_plan_message_reject(const evade_burn_plan_t& m) noexcept {
  return message_verdict(m).reject;
}

bool from_lcm(const evade_burn_plan_t& m, BurnPlan* out) noexcept {
  if (burn_plan_message_error(m) != nullptr) return false;
  BurnPlan p;
  p.plan_id = m.seq;
  p.n_impulses = m.n_impulses;
  for (int k = 0; k < m.n_impulses; ++k) {
    ImpulsiveBurn& b = p.impulses[static_cast<std::size_t>(k)];
    b.t_s = m.impulse_t_s[k];
    const double* r = m.impulse_dv_rsw_mps[k];
    const double* e = m.impulse_dv_eci_mps[k];
    b.dv_rsw_mps = Vec3(r[0], r[1], r[2]);
    b.dv_eci_valid = m.impulse_dv_eci_valid[k] == 1;
    b.dv_eci_mps = Vec3(e[0], e[1], e[2]);
  }
  p.source = m.source;
  if (m.source == kObservabilitySource) {
    ObservabilityPlanInfo& o = p.observability;
    o.valid = true;
    o.eps_rad = m.eps_rad;
    o.theta_rad = m.theta_rad;
    o.objective = m.objective;
    o.objective_value = m.objective_value;
    o.evaluations = m.evaluations;
  }
  *out = std::move(p);
  return true;
}

bool from_lcm(const evade_burn_plan_t& m, guidance::UplinkedPlan* out) noexcept {
  if (!from_lcm(m, &out->plan)) return false;
  out->epoch_utime_us = m.epoch_utime;
  out->frame = static_cast<guidance::PlanFrame>(m.frame);
  return true;
}

}  // namespace evade::guidance_lcm
