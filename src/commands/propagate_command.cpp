// `evade propagate` as a library call (see propagate_command.hpp): one orbit with the chosen
// gravity model, and for J2 the secular RAAN rate of Vallado, "Fundamentals of Astrodynamics
// and Applications", 4th ed., 2013, eq. 9-41, beside the observed osculating change.
#include "evade/commands/propagate_command.hpp"

#include <chrono>
#include <cstdio>
#include <string>

#include "evade/config/json_values.hpp"
#include "evade/config/read_elements.hpp"
#include "evade/config/read_params.hpp"
#include "evade/dynamics/orbit_propagator.hpp"

namespace evade::commands {
namespace {

const Param<PropagateParams> kPropagateRows[] = {
    EVADE_PARAM_REAL(PropagateParams, duration_s, "s", 1.0, 365.0 * kSecondsPerDay, false,
                     "propagation time span"),
    EVADE_PARAM_REAL(PropagateParams, rel_tol, "-", 1e-14, 1e-3, false,
                     "DOP853 relative tolerance (two-body-j2)"),
    EVADE_PARAM_REAL(PropagateParams, abs_tol, "m", 1e-12, 1e3, false,
                     "DOP853 absolute tolerance (m and m/s; two-body-j2)"),
};

}  // namespace

ParamTable<PropagateParams> propagate_params() noexcept {
  return make_param_table(kPropagateRows);
}

const char* gravity_model_name(GravityModel model) {
  return model == GravityModel::kTwoBody ? "two-body" : "two-body-j2";
}

PropagateRequest read_propagate_request(const config::Scenario& sc) {
  PropagateRequest req;
  req.epoch_utc = parse_calendar_utc(sc.get_string("epoch_utc", "2000-01-01 12:00:00"));
  req.earth = config::read_earth(sc);
  req.initial_elements = config::read_elements(sc, "orbit.", req.earth);
  config::require_params(sc, "propagation.", propagate_params(), req.params);
  config::read_params(sc, "propagation.", propagate_params(), &req.params);
  const std::string model =
      sc.get_enum("propagation.model", {"two-body", "two-body-j2"}, "two-body-j2");
  req.model = model == "two-body" ? GravityModel::kTwoBody : GravityModel::kTwoBodyJ2;
  sc.check_all_used();
  req.parameters = sc.used();
  return req;
}

PropagateResult run_propagate(const PropagateRequest& req) {
  PropagateResult r;
  r.epoch_utc = req.epoch_utc;
  r.duration_s = req.params.duration_s;
  r.end_utc = calendar_from_seconds_since_j2000(seconds_since_j2000_from_calendar(req.epoch_utc) +
                                                r.duration_s);
  r.model = req.model;
  r.parameters = req.parameters;
  AdaptiveOptions opt;
  opt.rel_tol = req.params.rel_tol;
  opt.abs_tol = req.params.abs_tol;
  const OrbitalElements& oe0 = req.initial_elements;
  const StateEci s0 = state_from_elements(oe0, req.earth.mu_m3ps2);
  const auto t0 = std::chrono::steady_clock::now();
  r.final_eci = propagate_orbit(s0, r.duration_s, req.model, req.earth, opt, &r.stats);
  r.runtime_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const OrbitalElements oe1 = elements_from_state(r.final_eci, req.earth.mu_m3ps2);
  const J2SecularRates rates = j2_secular_rates(oe0.a_m, oe0.e, oe0.i_rad, req.earth);
  r.delta_raan_deg = wrap_pi(oe1.raan_rad - oe0.raan_rad) * kRadToDeg;
  r.secular_delta_raan_deg = req.model == GravityModel::kTwoBodyJ2
                                 ? rates.raan_dot_radps * r.duration_s * kRadToDeg
                                 : 0.0;
  const StateEci kepler = propagate_orbit(s0, r.duration_s, GravityModel::kTwoBody, req.earth);
  r.j2_displacement_from_kepler_m = (r.final_eci.r_eci_m - kepler.r_eci_m).norm();
  return r;
}

nlohmann::json to_json(const PropagateResult& r) {
  nlohmann::json j;
  j["epoch_utc"] = format_calendar_utc(r.epoch_utc);
  j["end_utc"] = format_calendar_utc(r.end_utc);
  j["model"] = gravity_model_name(r.model);
  j["r_eci_m"] = config::vec_json(r.final_eci.r_eci_m);
  j["v_eci_mps"] = config::vec_json(r.final_eci.v_eci_mps);
  j["delta_raan_deg"] = r.delta_raan_deg;
  j["secular_delta_raan_deg"] = r.secular_delta_raan_deg;
  j["j2_displacement_from_kepler_m"] = r.j2_displacement_from_kepler_m;
  j["steps"] = r.stats.steps_accepted;
  j["rejected_steps"] = r.stats.steps_rejected;
  j["rhs_evaluations"] = r.stats.rhs_evaluations;
  j["runtime_s"] = r.runtime_s;
  j["parameters"] = r.parameters;
  return j;
}

std::string to_text(const PropagateResult& r) {
  const Vec3& p = r.final_eci.r_eci_m;
  const Vec3& v = r.final_eci.v_eci_mps;
  char buf[1024];
  // Every line is bounded (fixed formats of finite numbers): the counts are not needed.
  std::string t;
  (void)std::snprintf(buf, sizeof buf, "evade propagate: %s, %.0f s from %s UTC\n",
                      gravity_model_name(r.model), r.duration_s,
                      format_calendar_utc(r.epoch_utc).c_str());
  t += buf;
  (void)std::snprintf(buf, sizeof buf, "  final r_eci_m  = [%.3f, %.3f, %.3f] (ECI J2000)\n",
                      p.x(), p.y(), p.z());
  t += buf;
  (void)std::snprintf(buf, sizeof buf, "  final v_eci_mps = [%.6f, %.6f, %.6f] (ECI J2000)\n",
                      v.x(), v.y(), v.z());
  t += buf;
  (void)std::snprintf(buf, sizeof buf,
                      "  RAAN change %.4f deg (J2 secular rate predicts %.4f deg; osculating, so "
                      "short-period terms differ)\n",
                      r.delta_raan_deg, r.secular_delta_raan_deg);
  t += buf;
  (void)std::snprintf(buf, sizeof buf, "  position difference from pure two-body: %.1f m\n",
                      r.j2_displacement_from_kepler_m);
  t += buf;
  (void)std::snprintf(buf, sizeof buf, "  %ld steps (%ld rejected), %ld RHS evaluations, %.2f ms\n",
                      r.stats.steps_accepted, r.stats.steps_rejected, r.stats.rhs_evaluations,
                      r.runtime_s * 1e3);
  t += buf;
  return t;
}

}  // namespace evade::commands
