// Bindings of the planners: `evade plan threat-area` (paper 001, threat/threat_area_command.hpp),
// `evade plan formation` (paper 003, formation/formation_command.hpp) and `evade plan
// observability` (paper 004, observability/observability_command.hpp). Each request is built
// as its CLI command builds it (the scenario with its overrides, then the command's flags);
// the result is the command's JSON document and the BurnPlan the command would publish
// (the planner's make_burn_plan), or None when the planner has nothing to fly. The GIL is
// released while planning. Also the BurnPlan type (core/burn_plan.hpp), shared with
// `evade plan cam` (bind_assessment.cpp).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nanobind/stl/map.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include "bind_common.hpp"
#include "evade/core/burn_plan.hpp"
#include "evade/commands/formation_command.hpp"
#include "evade/observability/burn_plan.hpp"
#include "evade/commands/observability_command.hpp"
#include "evade/commands/plan_file.hpp"
#include "evade/threat/burn_plan.hpp"
#include "evade/commands/threat_area_command.hpp"

namespace evade::python {
namespace {

// The names of the plan file and of the observability objectives, from their one table each.
std::string source_name(int source) { return commands::plan_source_name(source); }
std::string objective_name(int objective) { return observability::plan_objective_name(objective); }

std::size_t impulse_count(const BurnPlan& p) {
  return static_cast<std::size_t>(std::max(0, std::min(p.n_impulses, BurnPlan::kMaxImpulses)));
}

NumpyArray<double> burn_times_s(const BurnPlan& p) {
  std::vector<double> t;
  for (std::size_t i = 0; i < impulse_count(p); ++i) t.push_back(p.impulses[i].t_s);
  return numpy_from_vector(std::move(t), {impulse_count(p)});
}

// Δv [m/s] of every impulse, (N, 3): RSW, or ECI (NaN rows where the plan has no ECI Δv).
NumpyArray<double> burn_dv_mps(const BurnPlan& p, bool eci) {
  std::vector<double> dv;
  for (std::size_t i = 0; i < impulse_count(p); ++i) {
    const ImpulsiveBurn& b = p.impulses[i];
    for (int k = 0; k < 3; ++k) {
      if (!eci) dv.push_back(b.dv_rsw_mps[k]);
      else dv.push_back(b.dv_eci_valid ? b.dv_eci_mps[k] : std::nan(""));
    }
  }
  return numpy_from_vector(std::move(dv), {impulse_count(p), 3});
}

NumpyArray<bool> burn_eci_valid(const BurnPlan& p) {
  const std::size_t n = impulse_count(p);
  bool* valid = new bool[n == 0 ? 1 : n];
  for (std::size_t i = 0; i < n; ++i) valid[i] = p.impulses[i].dv_eci_valid;
  nb::capsule owner(valid, [](void* q) noexcept { delete[] static_cast<bool*>(q); });
  const std::size_t shape[1] = {n};
  return NumpyArray<bool>(valid, 1, shape, owner);
}

// The JSON document and the plan (or None), the GIL held again.
nb::tuple result_pair(const nlohmann::json& j, const std::optional<BurnPlan>& plan) {
  return nb::make_tuple(json_to_python(j), plan ? nb::cast(*plan) : nb::none());
}

nb::tuple threat_area(const std::string& scenario, const std::vector<std::string>& sets,
                      const ParamMap& params, long seed,
                      bool eliminate, const std::vector<double>& sweep_dv_mps,
                      const std::vector<double>& sweep_transfer_s, std::int64_t plan_id) {
  commands::ThreatAreaRequest req = commands::read_threat_area_request(load_scenario(scenario, sets, params));
  if (seed >= 0) req.scenario.evasion.seed = static_cast<std::uint64_t>(seed);
  req.study.eliminate = eliminate;
  req.study.sweep_dv_mps = sweep_dv_mps;
  req.study.sweep_transfer_s = sweep_transfer_s;
  nlohmann::json j;
  std::optional<BurnPlan> plan;
  {
    nb::gil_scoped_release unlocked;
    const commands::ThreatAreaResult r = commands::run_threat_area(req);
    j = commands::to_json(r);
    // V_E = 0 (evasion.dv_mps = 0): no burn to fly.
    if (r.study.evasion.dv_mps > 0.0) plan = threat::make_burn_plan(r.study.evasion, plan_id);
  }
  return result_pair(j, plan);
}

nb::tuple formation_plan(const std::string& scenario, const std::vector<std::string>& sets,
                         bool numerical_limits, std::int64_t plan_id) {
  commands::FormationRequest req = commands::read_formation_request(load_scenario(scenario, sets));
  req.numerical_limits = numerical_limits;
  nlohmann::json j;
  std::optional<BurnPlan> plan;
  {
    nb::gil_scoped_release unlocked;
    const commands::FormationResult r = commands::run_formation(req);
    j = commands::to_json(r);
    // No maneuver needed, or an infeasible decision (its trade-off is never published).
    if (r.decision.maneuver_needed && r.decision.feasible) plan = commands::make_burn_plan(r, plan_id);
  }
  return result_pair(j, plan);
}

nb::tuple observability_plan(const std::string& scenario, const std::vector<std::string>& sets,
                             const std::string& objective, long seed, std::int64_t plan_id) {
  commands::ObservabilityOverrides ov;
  ov.objective = objective;
  ov.seed = seed;
  commands::ObservabilityRequest req =
      commands::read_observability_request(load_scenario(scenario, sets), ov);
  nlohmann::json j;
  BurnPlan plan;
  {
    nb::gil_scoped_release unlocked;
    const commands::ObservabilityResult r = commands::run_observability(req);
    j = commands::to_json(r);
    plan = observability::make_burn_plan(r.plan, plan_id);
  }
  return result_pair(j, plan);
}

nb::object observability_info(const BurnPlan& p) {
  if (!p.observability.valid) return nb::none();
  nb::dict d;
  d["eps_rad"] = p.observability.eps_rad;
  d["theta_rad"] = p.observability.theta_rad;
  d["objective"] = objective_name(p.observability.objective);
  d["objective_value"] = p.observability.objective_value;
  d["evaluations"] = p.observability.evaluations;
  return d;
}

}  // namespace

void bind_planners(nb::module_& m) {
  nb::class_<BurnPlan>(m, "BurnPlanNative", "A plan as the planners publish it (core/burn_plan.hpp).")
      .def_ro("plan_id", &BurnPlan::plan_id)
      .def_prop_ro("source", [](const BurnPlan& p) { return source_name(p.source); })
      .def_prop_ro("t_s", &burn_times_s, nb::rv_policy::move, "burn times after the plan's epoch [s]")
      .def_prop_ro("dv_rsw_mps", [](const BurnPlan& p) { return burn_dv_mps(p, false); },
                   nb::rv_policy::move, "(N, 3) Δv in RSW [m/s]")
      .def_prop_ro("dv_eci_mps", [](const BurnPlan& p) { return burn_dv_mps(p, true); },
                   nb::rv_policy::move, "(N, 3) Δv in ECI (J2000) [m/s], NaN where unknown")
      .def_prop_ro("dv_eci_valid", &burn_eci_valid, nb::rv_policy::move)
      .def_prop_ro("observability", &observability_info, "the observability planner's extras or None");
  m.def("plan_threat_area", &threat_area, nb::arg("scenario"), nb::arg("sets"), nb::arg("params"),
        nb::arg("seed"),
        nb::arg("eliminate"), nb::arg("sweep_dv_mps"), nb::arg("sweep_transfer_s"),
        nb::arg("plan_id"), "(JSON of `evade plan threat-area`, its BurnPlan or None)");
  m.def("plan_formation", &formation_plan, nb::arg("scenario"), nb::arg("sets"),
        nb::arg("numerical_limits"), nb::arg("plan_id"),
        "(JSON of `evade plan formation`, its BurnPlan or None)");
  m.def("plan_observability", &observability_plan, nb::arg("scenario"), nb::arg("sets"),
        nb::arg("objective"), nb::arg("seed"), nb::arg("plan_id"),
        "(JSON of `evade plan observability`, its BurnPlan)");
}

}  // namespace evade::python
