// `evade plan formation`: paper 003 (Duan et al.) — formation-constellation collision
// avoidance by a small semi-major-axis change. Prints the drift coefficients K_Ω, K_φ,
// K_am (paper eqs. 2, 4), Table 1 (limits per constraint and overall), the decision
// (direction, Δa, burn times, vis-viva Δv) and its verification by two-body + J2
// propagation (miss at the TCA, each constraint's minimum margin over T days).
// --numerical-limits adds Table 1 recomputed by bisection on propagated margins. --publish
// sends the decision's two burns (formation::make_burn_plan) as evade_burn_plan_t on LCM
// (plan_output.hpp, the same path as the other planners).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <vector>

#include "cli.hpp"
#include "evade/formation/burn_plan.hpp"
#include "plan_output.hpp"
#include "evade/formation/formation_scenario.hpp"
#include "evade/formation/limits.hpp"
#include "evade/formation/verification.hpp"

namespace evade::cli {
namespace {

using namespace evade::formation;

struct PlanFormationOptions {
  CommonOptions common;
  bool numerical_limits = false;
  PlanOutputOptions out;
};

nlohmann::json num(double v) {  // +inf (no limit) and NaN become null
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

bool is_angle(ConstraintKind k) {
  return k == ConstraintKind::kInterGroupRaan || k == ConstraintKind::kInterGroupPhase;
}

nlohmann::json burn_json(const AppliedBurn& b) {
  return {{"t_s", b.t_s},
          {"delta_a_m", b.delta_a_m},
          {"dv_tangential_mps", b.dv_mps},
          {"dv_approx_n_da_over_2_mps", b.dv_approx_mps},
          {"a_before_m", b.a_before_m}};
}

// Everything the command computes, in the order it computes it.
struct PlanResult {
  LimitsResult lim;
  Decision dec;
  Verification ver;
  std::vector<NumericalLimitRow> numl;  ///< --numerical-limits only
  double runtime_s = 0.0;
};

PlanResult plan(const PlanInputs& in, bool numerical) {
  PlanResult r;
  const auto t0 = std::chrono::steady_clock::now();
  r.lim = compute_limits(in.spec, in.threatened);
  std::cerr << "plan formation: limits done; deciding (propagating)...\n";
  r.dec = decide(in.spec, in.threatened, r.lim, in.conjunction, in.timing, in.propagation);
  std::cerr << "plan formation: decision done; verifying over T days...\n";
  r.ver = verify(in.spec, in.threatened, in.conjunction, r.dec, in.propagation);
  if (numerical) {
    std::cerr << "plan formation: numerical limits (bisection on propagated margins)...\n";
    r.numl = numerical_limits(in.spec, in.threatened, r.lim, r.dec.burn_time_s, in.propagation);
  }
  r.runtime_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

// Table 1: one row per constraint (angles in degrees), numerical limits beside when asked.
nlohmann::json limits_json(const PlanResult& r, bool numerical) {
  nlohmann::json rows = nlohmann::json::array();
  for (std::size_t k = 0; k < r.lim.rows.size(); ++k) {
    const ConstraintLimit& row = r.lim.rows[k];
    const bool ang = is_angle(row.def.kind);
    const double sc_out = ang ? kRadToDeg : 1.0;
    nlohmann::json jr = {{"constraint", row.def.name},
                         {"kind", constraint_kind_name(row.def.kind)},
                         {"unit", ang ? "deg" : "m"},
                         {"current_deviation", row.deviation * sc_out},
                         {"band", {row.def.lower * sc_out, row.def.upper * sc_out}},
                         {"rate_per_m_day", row.rate_per_m_day * sc_out},
                         {"raise_max_m", num(row.raise_max_m)},
                         {"lower_max_m", num(row.lower_max_m)},
                         {"already_violated", row.already_violated}};
    if (numerical) {
      jr["numerical_raise_max_m"] = num(r.numl[k].raise_max_m);
      jr["numerical_lower_max_m"] = num(r.numl[k].lower_max_m);
      jr["numerical_propagations"] = r.numl[k].propagations;
    }
    rows.push_back(jr);
  }
  return rows;
}

nlohmann::json option_json(const DirectionOption& d) {
  return {{"required_delta_a_m", num(d.required_delta_a_m)},
          {"limit_m", num(d.limit_m)},
          {"feasible", d.feasible},
          {"miss_at_required_m", num(d.miss_at_required_m)},
          {"miss_at_limit_m", num(d.miss_at_limit_m)},
          {"violated_constraints", d.violated}};
}

nlohmann::json decision_json(const Decision& dec, const PlanInputs& in) {
  nlohmann::json jb = nlohmann::json::array();
  for (const AppliedBurn& b : dec.burns) jb.push_back(burn_json(b));
  return {{"maneuver_needed", dec.maneuver_needed},
          {"feasible", dec.feasible},
          {"direction", dec.direction},
          {"delta_a_m", dec.delta_a_m},
          {"burn_time_s", dec.burn_time_s},
          {"burn_before_tca_s", in.timing.burn_before_tca_s},
          {"restore_time_s", dec.restore_time_s},
          {"restore_after_tca_s", in.timing.restore_after_tca_s},
          {"restore", dec.restore},
          {"burns", jb},
          {"nominal_miss_m", dec.nominal_miss_m},
          {"required_miss_m", in.conjunction.required_miss_m},
          {"predicted_miss_m", dec.predicted_miss_m},
          {"raise", option_json(dec.raise)},
          {"lower", option_json(dec.lower)},
          {"summary", dec.summary}};
}

nlohmann::json verification_json(const Verification& ver, const LimitsResult& lim) {
  nlohmann::json vr = nlohmann::json::array();
  for (std::size_t r = 0; r < ver.rows.size(); ++r) {
    const ConstraintCheck& c = ver.rows[r];
    const double sc_out = is_angle(lim.rows[r].def.kind) ? kRadToDeg : 1.0;
    vr.push_back({{"constraint", c.name},
                  {"unit", is_angle(lim.rows[r].def.kind) ? "deg" : "m"},
                  {"initial_deviation", c.initial_deviation * sc_out},
                  {"final_deviation", c.final_deviation * sc_out},
                  {"min_margin", c.min_margin * sc_out},
                  {"t_min_margin_s", c.t_min_margin_s},
                  {"kept", c.kept}});
  }
  return {{"model", "two-body + J2, DOP853"},
          {"miss_at_tca_m", ver.miss_at_tca_m},
          {"closest_approach_offset_s", ver.closest_approach_offset_s},
          {"clears", ver.clears},
          {"window_end_s", ver.window_end_s},
          {"constraints", vr},
          {"all_constraints_kept", ver.all_kept}};
}

nlohmann::json result_json(const PlanInputs& in, const PlanResult& r, bool numerical,
                           const config::Scenario& sc) {
  nlohmann::json j;
  j["paper"] = "003 Duan et al., formation collision avoidance by small semi-major-axis change";
  j["threatened"] = in.spec.sat_name(in.threatened);
  j["k_omega_rad_per_m_day"] = r.lim.k.k_omega_rad_per_m_day;
  j["k_omega_deg_per_m_day"] = r.lim.k.k_omega_rad_per_m_day * kRadToDeg;
  j["k_omega_paper_rad_per_m_day"] = 2.0953e-8;
  j["k_phi_rad_per_m_day"] = r.lim.k.k_phi_rad_per_m_day;
  j["k_phi_kepler_rad_per_m_day"] = r.lim.k.k_phi_kepler_rad_per_m_day;
  j["k_am_m_per_m_day"] = r.lim.k.k_am_m_per_m_day;
  j["horizon_days"] = in.spec.horizon_days;
  j["limits"] = limits_json(r, numerical);
  j["raise_max_m"] = num(r.lim.raise_max_m);
  j["lower_max_m"] = num(r.lim.lower_max_m);
  j["raise_binding"] = r.lim.raise_binding;
  j["lower_binding"] = r.lim.lower_binding;
  j["decision"] = decision_json(r.dec, in);
  j["verification"] = verification_json(r.ver, r.lim);
  j["runtime_s"] = r.runtime_s;
  j["parameters"] = sc.used();
  return j;
}

void print_text(const PlanInputs& in, const PlanResult& r) {
  const LimitsResult& lim = r.lim;
  std::printf("evade plan formation (paper 003): threatened %s, T = %.2f days\n",
              in.spec.sat_name(in.threatened).c_str(), in.spec.horizon_days);
  std::printf("  K_Omega = %.5e rad/(m day) (paper 2.0953e-8), K_phi = %.5e rad/(m day), "
              "K_am = %.3f m/(m day)\n",
              lim.k.k_omega_rad_per_m_day, lim.k.k_phi_rad_per_m_day, lim.k.k_am_m_per_m_day);
  std::printf("  %-34s %12s %12s\n", "Table 1 constraint", "raise_max_m", "lower_max_m");
  for (const ConstraintLimit& row : lim.rows) {
    std::printf("  %-34s %12.3f %12.3f%s\n", row.def.name.c_str(), row.raise_max_m,
                row.lower_max_m, row.already_violated ? "  ALREADY VIOLATED" : "");
  }
  std::printf("  %-34s %12.3f %12.3f\n", "overall", lim.raise_max_m, lim.lower_max_m);
  std::printf("  decision: %s\n", r.dec.summary.c_str());
  for (const AppliedBurn& b : r.dec.burns) {
    std::printf("    burn t = %.0f s: delta_a %+.3f m, dv %+.5f m/s\n", b.t_s, b.delta_a_m, b.dv_mps);
  }
  std::printf("  verification: miss at TCA %.1f m (%s); constraints %s\n", r.ver.miss_at_tca_m,
              r.ver.clears ? "clears" : "DOES NOT CLEAR",
              r.ver.all_kept ? "all kept" : "SOME VIOLATED");
  for (const ConstraintCheck& c : r.ver.rows) {
    std::printf("    %-34s min margin %12.6g %s\n", c.name.c_str(), c.min_margin,
                c.kept ? "" : "VIOLATED");
  }
}

int run_plan_formation(const PlanFormationOptions& o) {
  const config::Scenario sc = load_scenario(o.common);
  const PlanInputs in = read_plan_inputs(sc);
  sc.check_all_used();
  const PlanResult r = plan(in, o.numerical_limits);
  nlohmann::json j = result_json(in, r, o.numerical_limits, sc);
  int uplink_rc = 0;
  if (plan_wanted(o.out)) {
    const BurnPlan bp = make_burn_plan(in.spec, in.threatened, r.dec, in.propagation, plan_id(o.out));
    uplink_rc = output_plan(o.out, bp, &j);
  }
  if (o.common.json) {
    print_json(j);
  } else {
    print_text(in, r);
  }
  return uplink_rc;  // 0, or the uplink's 3 (rejected) / 4 (no acknowledgement)
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<PlanFormationOptions>();
  add_common_options(app, o->common, "seed3");
  app.add_flag("--numerical-limits", o->numerical_limits,
               "also compute Table 1 by bisection on propagated margins (slower)");
  add_plan_output_options(app, o->out);
  return [o]() { return run_plan_formation(*o); };
}

const bool kRegistered = register_command(
    {{"plan", "formation"},
     "Formation collision avoidance by a small semi-major-axis change (paper 003)",
     &setup});

}  // namespace
}  // namespace evade::cli
