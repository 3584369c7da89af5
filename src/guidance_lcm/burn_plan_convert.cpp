// BurnPlan <-> evade_burn_plan_t (burn_plan_convert.hpp): the checks on either side, then a
// field-by-field copy.
#include "evade/guidance_lcm/burn_plan_convert.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace evade::guidance_lcm {
namespace {

constexpr int kObservabilitySource = static_cast<int>(PlanSource::kObservability);

bool known_source(int s) noexcept {
  return s == static_cast<int>(PlanSource::kUnknown) ||
         s == static_cast<int>(PlanSource::kThreatArea) ||
         s == static_cast<int>(PlanSource::kFormation) || s == kObservabilitySource;
}
bool known_objective(int k) noexcept {
  return k >= static_cast<int>(PlanObjective::kPaper) &&
         k <= static_cast<int>(PlanObjective::kEstimation);
}
bool finite3(const double* v) noexcept {
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

void check_impulses(const BurnPlan& p) {
  if (p.n_impulses < 0 || p.n_impulses > BurnPlan::kMaxImpulses)
    bad("n_impulses", "= " + std::to_string(p.n_impulses) + ": must be in [0, " +
                          std::to_string(BurnPlan::kMaxImpulses) + "]");
  if (p.n_impulses != 1)
    bad("n_impulses", "= " + std::to_string(p.n_impulses) +
                          ": evade_burn_plan_t carries exactly one impulse (a plan is never "
                          "published in part)");
  const ImpulsiveBurn& b = p.impulses[0];
  require_finite("impulses[0].t_s", b.t_s);
  require_finite("impulses[0].dv_rsw_mps", b.dv_rsw_mps);
  if (b.dv_eci_valid) require_finite("impulses[0].dv_eci_mps", b.dv_eci_mps);
}

void check_source(const BurnPlan& p) {
  if (!known_source(p.source))
    bad("source", "= " + std::to_string(p.source) +
                      ": unknown planner code (allowed: 0 unknown, 1 threat-area, 3 formation, "
                      "4 observability)");
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

}  // namespace

void to_lcm(const BurnPlan& plan, std::int64_t utime, std::int64_t seq, evade_burn_plan_t* out) {
  check_impulses(plan);
  check_source(plan);
  const ImpulsiveBurn& b = plan.impulses[0];
  const ObservabilityPlanInfo& o = plan.observability;
  evade_burn_plan_t m{};
  m.utime = utime;
  m.seq = seq;
  m.burn_time_s = b.t_s;
  for (int i = 0; i < 3; ++i) {
    m.dv_lvlh_mps[i] = b.dv_rsw_mps(i);
    m.dv_eci_mps[i] = b.dv_eci_valid ? b.dv_eci_mps(i) : 0.0;
  }
  m.dv_eci_valid = b.dv_eci_valid ? 1 : 0;
  m.dv_mps = b.dv_rsw_mps.norm();
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

const char* burn_plan_message_error(const evade_burn_plan_t& m) noexcept {
  if (m.dv_eci_valid != 0 && m.dv_eci_valid != 1)
    return "evade_burn_plan_t.dv_eci_valid: must be 0 or 1";
  if (!std::isfinite(m.burn_time_s)) return "evade_burn_plan_t.burn_time_s: not finite";
  if (!finite3(m.dv_lvlh_mps)) return "evade_burn_plan_t.dv_lvlh_mps: not finite";
  if (m.dv_eci_valid == 1 && !finite3(m.dv_eci_mps))
    return "evade_burn_plan_t.dv_eci_mps: not finite";
  if (!std::isfinite(m.dv_mps)) return "evade_burn_plan_t.dv_mps: not finite";
  if (!known_source(m.source))
    return "evade_burn_plan_t.source: unknown planner code (allowed 0, 1, 3, 4)";
  if (m.source != kObservabilitySource) return nullptr;
  if (!known_objective(m.objective))
    return "evade_burn_plan_t.objective: allowed 0 paper, 1 los-change, 2 estimation";
  if (!std::isfinite(m.eps_rad) || !std::isfinite(m.theta_rad))
    return "evade_burn_plan_t.eps_rad/theta_rad: not finite";
  if (!std::isfinite(m.objective_value)) return "evade_burn_plan_t.objective_value: not finite";
  if (m.evaluations < 0) return "evade_burn_plan_t.evaluations: must be >= 0";
  return nullptr;
}

bool from_lcm(const evade_burn_plan_t& m, BurnPlan* out) noexcept {
  if (burn_plan_message_error(m) != nullptr) return false;
  BurnPlan p;
  p.plan_id = m.seq;
  p.n_impulses = 1;
  ImpulsiveBurn& b = p.impulses[0];
  b.t_s = m.burn_time_s;
  b.dv_rsw_mps = Vec3(m.dv_lvlh_mps[0], m.dv_lvlh_mps[1], m.dv_lvlh_mps[2]);
  b.dv_eci_valid = m.dv_eci_valid == 1;
  b.dv_eci_mps = Vec3(m.dv_eci_mps[0], m.dv_eci_mps[1], m.dv_eci_mps[2]);
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
  *out = p;
  return true;
}

}  // namespace evade::guidance_lcm
