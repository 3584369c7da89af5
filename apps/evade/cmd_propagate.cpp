// `evade propagate`: the foundation demo. Propagates one orbit with the chosen gravity model
// and reports the final state, the element changes, and for J2 the analytic secular rates
// (Vallado eq. 9-41, 9-42) beside the numerically observed drift. With --tle or --omm it
// propagates every object of a catalog with SGP4 instead (cmd_propagate_tle.cpp).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "cli.hpp"
#include "cmd_propagate_tle.hpp"
#include "evade/config/read_params.hpp"
#include "evade/core/constants.hpp"
#include "evade/core/elements.hpp"
#include "evade/core/epoch.hpp"
#include "evade/dynamics/gravity.hpp"
#include "evade/dynamics/orbit_propagator.hpp"

namespace evade::cli {
namespace {

struct PropagateOptions {
  CommonOptions common;
  CatalogPropagateOptions catalog;  ///< --tle/--omm path
};

// What the scenario asks for (read_earth for the Earth model; the orbit's elements and the
// run's settings through typed reads: the a_m range depends on earth.re_m).
struct PropagateInputs {
  CalendarUtc epoch;
  EarthModel earth;
  OrbitalElements oe;
  double duration_s = 0.0;
  std::string model_name;
  GravityModel model = GravityModel::kTwoBodyJ2;
  AdaptiveOptions opt;
};

PropagateInputs read_inputs(const config::Scenario& sc) {
  PropagateInputs in;
  in.epoch = parse_calendar_utc(sc.get_string("epoch_utc", "2000-01-01 12:00:00"));
  in.earth = config::read_earth(sc);
  OrbitalElements& oe = in.oe;
  oe.a_m = sc.get_double("orbit.a_m", in.earth.re_m, 1e9);
  oe.e = sc.get_double("orbit.e", 0.0, 0.99);
  oe.i_rad = sc.get_double("orbit.i_deg", 0.0, 180.0) * kDegToRad;
  oe.raan_rad = sc.get_double("orbit.raan_deg", -360.0, 360.0) * kDegToRad;
  oe.argp_rad = sc.get_double("orbit.argp_deg", -360.0, 360.0) * kDegToRad;
  oe.true_anomaly_rad = sc.get_double("orbit.true_anomaly_deg", -360.0, 360.0) * kDegToRad;
  if (oe.a_m * (1.0 - oe.e) <= in.earth.re_m)
    throw config::ConfigError(sc.source() + ": key 'orbit.a_m'/'orbit.e': perigee radius " +
                              std::to_string(oe.a_m * (1.0 - oe.e)) + " m is inside the Earth (re_m = " +
                              std::to_string(in.earth.re_m) + ")");
  in.duration_s = sc.get_double("propagation.duration_s", 1.0, 365.0 * kSecondsPerDay);
  in.model_name = sc.get_enum("propagation.model", {"two-body", "two-body-j2"}, "two-body-j2");
  in.opt.rel_tol = sc.get_double("propagation.rel_tol", 1e-14, 1e-3, in.opt.rel_tol);
  in.opt.abs_tol = sc.get_double("propagation.abs_tol", 1e-12, 1e3, in.opt.abs_tol);
  in.model = in.model_name == "two-body" ? GravityModel::kTwoBody : GravityModel::kTwoBodyJ2;
  return in;
}

struct PropagateResult {
  StateEci s1;            ///< final state with the chosen model
  StateEci s1_kepler;     ///< final state, two-body
  IntegrationStats stats;
  double runtime_s = 0.0;
  double d_raan_deg = 0.0;        ///< osculating RAAN change
  double secular_raan_deg = 0.0;  ///< J2 secular prediction (0 for two-body)
};

PropagateResult propagate(const PropagateInputs& in) {
  PropagateResult r;
  const StateEci s0 = state_from_elements(in.oe, in.earth.mu_m3ps2);
  const auto t0 = std::chrono::steady_clock::now();
  r.s1 = propagate_orbit(s0, in.duration_s, in.model, in.earth, in.opt, &r.stats);
  r.runtime_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const OrbitalElements oe1 = elements_from_state(r.s1, in.earth.mu_m3ps2);
  const J2SecularRates rates = j2_secular_rates(in.oe.a_m, in.oe.e, in.oe.i_rad, in.earth);
  r.d_raan_deg = wrap_pi(oe1.raan_rad - in.oe.raan_rad) * kRadToDeg;
  r.secular_raan_deg = in.model == GravityModel::kTwoBodyJ2 ? rates.raan_dot_radps * in.duration_s * kRadToDeg : 0.0;
  r.s1_kepler = propagate_orbit(s0, in.duration_s, GravityModel::kTwoBody, in.earth);
  return r;
}

nlohmann::json result_json(const PropagateInputs& in, const PropagateResult& r,
                           const config::Scenario& sc) {
  nlohmann::json j;
  j["epoch_utc"] = format_calendar_utc(in.epoch);
  j["end_utc"] = format_calendar_utc(calendar_from_seconds_since_j2000(seconds_since_j2000_from_calendar(in.epoch) + in.duration_s));
  j["model"] = in.model_name;
  j["r_eci_m"] = {r.s1.r_eci_m.x(), r.s1.r_eci_m.y(), r.s1.r_eci_m.z()};
  j["v_eci_mps"] = {r.s1.v_eci_mps.x(), r.s1.v_eci_mps.y(), r.s1.v_eci_mps.z()};
  j["delta_raan_deg"] = r.d_raan_deg;
  j["secular_delta_raan_deg"] = r.secular_raan_deg;
  j["j2_displacement_from_kepler_m"] = (r.s1.r_eci_m - r.s1_kepler.r_eci_m).norm();
  j["steps"] = r.stats.steps_accepted;
  j["rejected_steps"] = r.stats.steps_rejected;
  j["rhs_evaluations"] = r.stats.rhs_evaluations;
  j["runtime_s"] = r.runtime_s;
  j["parameters"] = sc.used();
  return j;
}

void print_text(const PropagateInputs& in, const PropagateResult& r) {
  const StateEci& s1 = r.s1;
  std::printf("evade propagate: %s, %.0f s from %s\n", in.model_name.c_str(), in.duration_s, format_calendar_utc(in.epoch).c_str());
  std::printf("  final r_eci_m  = [%.3f, %.3f, %.3f]\n", s1.r_eci_m.x(), s1.r_eci_m.y(), s1.r_eci_m.z());
  std::printf("  final v_eci_mps = [%.6f, %.6f, %.6f]\n", s1.v_eci_mps.x(), s1.v_eci_mps.y(), s1.v_eci_mps.z());
  std::printf("  RAAN change %.4f deg (J2 secular rate predicts %.4f deg; osculating, so short-period terms differ)\n",
              r.d_raan_deg, r.secular_raan_deg);
  std::printf("  position difference from pure two-body: %.1f m\n", (s1.r_eci_m - r.s1_kepler.r_eci_m).norm());
  std::printf("  %ld steps (%ld rejected), %ld RHS evaluations, %.2f ms\n", r.stats.steps_accepted,
              r.stats.steps_rejected, r.stats.rhs_evaluations, r.runtime_s * 1e3);
}

int run_propagate(const PropagateOptions& o) {
  if (!o.catalog.tle_path.empty() || !o.catalog.omm_path.empty()) {
    if (!o.common.sets.empty()) throw std::invalid_argument("--set applies to the scenario, not to --tle/--omm");
    CatalogPropagateOptions c = o.catalog;
    c.json = o.common.json;
    return run_propagate_catalog(c);
  }
  const config::Scenario sc = load_scenario(o.common);
  const PropagateInputs in = read_inputs(sc);
  sc.check_all_used();
  const PropagateResult r = propagate(in);
  if (o.common.json) {
    print_json(result_json(in, r, sc));
  } else {
    print_text(in, r);
  }
  return 0;
}

void add_catalog_options(CLI::App& app, CatalogPropagateOptions& c) {
  auto* tle = app.add_option("--tle", c.tle_path, "TLE/3LE file: propagate every object with SGP4");
  auto* omm = app.add_option("--omm", c.omm_path, "CCSDS OMM (KVN or XML) or GP JSON/CSV file, as --tle");
  tle->excludes(omm);
  app.add_option("--span-s", c.span_s, "with --tle/--omm: time span from the latest element epoch [s]");
  app.add_option("--step-s", c.step_s, "with --tle/--omm: output step [s]");
  app.add_option("--frame", c.frame, "with --tle/--omm: teme or eci (J2000)");
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<PropagateOptions>();
  add_common_options(app, o->common, "demo-leo");
  add_catalog_options(app, o->catalog);
  return [o]() { return run_propagate(*o); };
}

const bool kRegistered = register_command(
    {{"propagate"},
     "Propagate one orbit (two-body or two-body + J2): the foundation demo",
     &setup});

}  // namespace
}  // namespace evade::cli
