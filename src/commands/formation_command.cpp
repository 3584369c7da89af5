// `evade plan formation` as a library call: the request read from the scenario, the plan
// (Table 1, decision, verification, optionally numerical limits), its JSON (the keys, order
// and numbers the command has always printed: angle rows in degrees, +inf and NaN as null)
// and its text (each figure with its unit; constraint margins in rad or m).
// Paper 003 (Duan You, Su Peng, Gao Yan, Qi Yajiang, Yang Shiqi, "Collision avoidance of
// formation-flying satellites under multiple configuration constraints"); see
// evade/commands/formation_command.hpp.
#include "evade/commands/formation_command.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "evade/core/constants.hpp"
#include "evade/core/text_format.hpp"
#include "evade/formation/burn_plan.hpp"

namespace evade::commands {
namespace {

nlohmann::json num(double v) {  // +inf (no limit) and NaN become null
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

bool is_angle(formation::ConstraintKind k) {
  return k == formation::ConstraintKind::kInterGroupRaan || k == formation::ConstraintKind::kInterGroupPhase;
}

nlohmann::json burn_json(const formation::AppliedBurn& b) {
  return {{"t_s", b.t_s},
          {"delta_a_m", b.delta_a_m},
          {"dv_tangential_mps", b.dv_mps},
          {"dv_approx_n_da_over_2_mps", b.dv_approx_mps},
          {"a_before_m", b.a_before_m}};
}

// Table 1: one row per constraint (angles in degrees), numerical limits beside when asked.
nlohmann::json limits_json(const FormationResult& r) {
  nlohmann::json rows = nlohmann::json::array();
  for (std::size_t k = 0; k < r.limits.rows.size(); ++k) {
    const formation::ConstraintLimit& row = r.limits.rows[k];
    const bool ang = is_angle(row.def.kind);
    const double sc_out = ang ? kRadToDeg : 1.0;
    nlohmann::json jr = {{"constraint", row.def.name},
                         {"kind", formation::constraint_kind_name(row.def.kind)},
                         {"unit", ang ? "deg" : "m"},
                         {"current_deviation", row.deviation * sc_out},
                         {"band", {row.def.lower * sc_out, row.def.upper * sc_out}},
                         {"rate_per_m_day", row.rate_per_m_day * sc_out},
                         {"raise_max_m", num(row.raise_max_m)},
                         {"lower_max_m", num(row.lower_max_m)},
                         {"already_violated", row.already_violated}};
    if (r.numerical) {
      jr["numerical_raise_max_m"] = num(r.numerical_limits[k].raise_max_m);
      jr["numerical_lower_max_m"] = num(r.numerical_limits[k].lower_max_m);
      jr["numerical_propagations"] = r.numerical_limits[k].propagations;
    }
    rows.push_back(jr);
  }
  return rows;
}

nlohmann::json option_json(const formation::DirectionOption& d) {
  return {{"required_delta_a_m", num(d.required_delta_a_m)},
          {"limit_m", num(d.limit_m)},
          {"feasible", d.feasible},
          {"miss_at_required_m", num(d.miss_at_required_m)},
          {"miss_at_limit_m", num(d.miss_at_limit_m)},
          {"violated_constraints", d.violated}};
}

nlohmann::json decision_json(const formation::Decision& dec, const formation::PlanInputs& in) {
  nlohmann::json jb = nlohmann::json::array();
  for (const formation::AppliedBurn& b : dec.burns) jb.push_back(burn_json(b));
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

nlohmann::json verification_json(const formation::Verification& ver, const formation::LimitsResult& lim) {
  nlohmann::json vr = nlohmann::json::array();
  for (std::size_t r = 0; r < ver.rows.size(); ++r) {
    const formation::ConstraintCheck& c = ver.rows[r];
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

void say(const FormationTextSink& sink, const char* line) {
  if (sink) sink(line);
}

// Table 1 (analytic limits; the numerical ones beside them when computed).
std::string limits_text(const FormationResult& r) {
  const formation::LimitsResult& lim = r.limits;
  std::string t = format_text("  %-34s %12s %12s%s\n", "Table 1 constraint", "raise_max_m", "lower_max_m",
                         r.numerical ? "  numerical_raise_m numerical_lower_m" : "");
  for (std::size_t k = 0; k < lim.rows.size(); ++k) {
    const formation::ConstraintLimit& row = lim.rows[k];
    t += format_text("  %-34s %12.3f %12.3f", row.def.name.c_str(), row.raise_max_m, row.lower_max_m);
    if (r.numerical) {
      t += format_text("  %17.3f %17.3f", r.numerical_limits[k].raise_max_m,
                  r.numerical_limits[k].lower_max_m);
    }
    t += row.already_violated ? "  ALREADY VIOLATED\n" : "\n";
  }
  return t + format_text("  %-34s %12.3f %12.3f\n", "overall", lim.raise_max_m, lim.lower_max_m);
}

std::string decision_text(const FormationResult& r) {
  const formation::Decision& dec = r.decision;
  std::string t = format_text("  decision: %s\n", dec.summary.c_str());
  for (const formation::AppliedBurn& b : dec.burns) {
    t += format_text("    burn t = %.0f s after the epoch: delta_a %+.3f m, dv %+.5f m/s (tangential)\n",
                b.t_s, b.delta_a_m, b.dv_mps);
  }
  return t + format_text("  conjunction: TCA t = %.0f s after the epoch; miss without maneuver %.1f m, "
                    "predicted %.1f m, required %.1f m\n",
                    r.inputs.conjunction.tca_s, dec.nominal_miss_m, dec.predicted_miss_m,
                    r.inputs.conjunction.required_miss_m);
}

// Each constraint's smallest margin to its band over the window: radians for the
// inter-group RAAN and phase, metres for the box constraints.
std::string verification_text(const FormationResult& r) {
  const formation::Verification& ver = r.verification;
  std::string t = format_text("  verification (two-body + J2): miss at TCA %.1f m (%s); constraints %s\n",
                         ver.miss_at_tca_m, ver.clears ? "clears" : "DOES NOT CLEAR",
                         ver.all_kept ? "all kept" : "SOME VIOLATED");
  for (std::size_t k = 0; k < ver.rows.size(); ++k) {
    const formation::ConstraintCheck& c = ver.rows[k];
    const bool ang = k < r.limits.rows.size() && is_angle(r.limits.rows[k].def.kind);
    t += format_text("    %-34s min margin %12.6g %-3s at t = %.0f s%s\n", c.name.c_str(), c.min_margin,
                ang ? "rad" : "m", c.t_min_margin_s, c.kept ? "" : "  VIOLATED");
  }
  return t;
}

}  // namespace

FormationRequest read_formation_request(const config::Scenario& sc) {
  FormationRequest req;
  req.inputs = read_plan_inputs(sc);
  sc.check_all_used();
  req.scenario_used = sc.used();
  return req;
}

FormationResult run_formation(const FormationRequest& req) {
  const formation::PlanInputs& in = req.inputs;
  FormationResult r;
  r.inputs = in;
  r.scenario_used = req.scenario_used;
  const auto t0 = std::chrono::steady_clock::now();
  r.limits = formation::compute_limits(in.spec, in.threatened);
  say(req.progress, "plan formation: limits done; deciding (propagating)...");
  r.decision = formation::decide(in.spec, in.threatened, r.limits, in.conjunction, in.timing, in.propagation);
  say(req.progress, "plan formation: decision done; verifying over T days...");
  r.verification = formation::verify(in.spec, in.threatened, in.conjunction, r.decision, in.propagation);
  if (req.numerical_limits) {
    say(req.progress, "plan formation: numerical limits (bisection on propagated margins)...");
    r.numerical = true;
    r.numerical_limits = formation::numerical_limits(in.spec, in.threatened, r.limits,
                                          r.decision.burn_time_s, in.propagation);
  }
  r.runtime_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

BurnPlan make_burn_plan(const FormationResult& r, std::int64_t plan_id) {
  const formation::PlanInputs& in = r.inputs;
  return formation::make_burn_plan(in.spec, in.threatened, r.decision, in.propagation, plan_id);
}

nlohmann::json to_json(const FormationResult& r) {
  const formation::PlanInputs& in = r.inputs;
  nlohmann::json j;
  j["paper"] = "003 Duan et al., formation collision avoidance by small semi-major-axis change";
  j["threatened"] = in.spec.sat_name(in.threatened);
  j["k_omega_rad_per_m_day"] = r.limits.k.k_omega_rad_per_m_day;
  j["k_omega_deg_per_m_day"] = r.limits.k.k_omega_rad_per_m_day * kRadToDeg;
  j["k_omega_paper_rad_per_m_day"] = 2.0953e-8;
  j["k_phi_rad_per_m_day"] = r.limits.k.k_phi_rad_per_m_day;
  j["k_phi_kepler_rad_per_m_day"] = r.limits.k.k_phi_kepler_rad_per_m_day;
  j["k_am_m_per_m_day"] = r.limits.k.k_am_m_per_m_day;
  j["horizon_days"] = in.spec.horizon_days;
  j["limits"] = limits_json(r);
  j["raise_max_m"] = num(r.limits.raise_max_m);
  j["lower_max_m"] = num(r.limits.lower_max_m);
  j["raise_binding"] = r.limits.raise_binding;
  j["lower_binding"] = r.limits.lower_binding;
  j["decision"] = decision_json(r.decision, in);
  j["verification"] = verification_json(r.verification, r.limits);
  j["runtime_s"] = r.runtime_s;
  j["parameters"] = r.scenario_used;
  return j;
}

std::string to_text(const FormationResult& r) {
  const formation::LimitsResult& lim = r.limits;
  std::string t = format_text("evade plan formation (paper 003): threatened %s, T = %.2f days\n",
                         r.inputs.spec.sat_name(r.inputs.threatened).c_str(),
                         r.inputs.spec.horizon_days);
  t += format_text("  K_Omega = %.5e rad/(m day) (paper 2.0953e-8), K_phi = %.5e rad/(m day), "
              "K_am = %.3f m/(m day)\n",
              lim.k.k_omega_rad_per_m_day, lim.k.k_phi_rad_per_m_day, lim.k.k_am_m_per_m_day);
  return t + limits_text(r) + decision_text(r) + verification_text(r);
}

}  // namespace evade::commands
