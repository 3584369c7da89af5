// Scenario reader for paper 003's planner (see formation_scenario.hpp).
#include "evade/formation/formation_scenario.hpp"

#include <stdexcept>
#include <string>

namespace evade::formation {

PlanInputs read_plan_inputs(const config::Scenario& sc) {
  PlanInputs in;
  FormationSpec& f = in.spec;
  f.earth.mu_m3ps2 = sc.get_double("earth.mu_m3ps2", 1e13, 1e15, f.earth.mu_m3ps2);
  f.earth.j2 = sc.get_double("earth.j2", 0.0, 1e-2, f.earth.j2);
  f.earth.re_m = sc.get_double("earth.re_m", 6e6, 7e6, f.earth.re_m);
  f.side_length_m = sc.get_double("formation.side_length_m", 1.0, 1e7);
  f.box_delta_m = sc.get_double("formation.box_delta_m", 1e-3, f.side_length_m / 8.0);
  f.raan_tolerance_rad = sc.get_double("formation.raan_tolerance_deg", 1e-9, 90.0) * kDegToRad;
  f.phase_tolerance_rad = sc.get_double("formation.phase_tolerance_deg", 1e-9, 90.0) * kDegToRad;
  f.horizon_days = sc.get_double("formation.horizon_days", 1e-3, 60.0);
  const std::size_t ng = sc.list_size("formation.groups");
  if (ng < 2) {
    throw config::ConfigError(sc.source() + ": key 'formation.groups' has " + std::to_string(ng) +
                              " groups; allowed: a list of at least 2 (a reference and another)");
  }
  const char* roles[3] = {"chief", "deputy1", "deputy2"};
  std::vector<std::string> names;
  for (std::size_t g = 0; g < ng; ++g) {
    const std::string p = "formation.groups." + std::to_string(g) + ".";
    Group gr;
    gr.name = sc.get_string(p + "name");
    for (const std::string& n : names) {
      if (n == gr.name) {
        throw config::ConfigError(sc.source() + ": key '" + p + "name' = '" + gr.name +
                                  "' repeats an earlier group; allowed: unique names");
      }
    }
    names.push_back(gr.name);
    gr.nominal_raan_offset_rad =
        sc.get_double(p + "nominal_raan_offset_deg", -360.0, 360.0) * kDegToRad;
    gr.nominal_phase_offset_rad =
        sc.get_double(p + "nominal_phase_offset_deg", -360.0, 360.0) * kDegToRad;
    for (int r = 0; r < 3; ++r) {
      const std::string q = p + roles[r] + ".";
      MeanElements& m = gr.sats[static_cast<std::size_t>(r)];
      m.a_m = sc.get_double(q + "a_m", f.earth.re_m + 1e5, 5e7);
      m.e = sc.get_double(q + "e", 0.0, 0.01, 0.0);
      m.i_rad = sc.get_double(q + "i_deg", 0.1, 179.9) * kDegToRad;
      m.raan_rad = sc.get_double(q + "raan_deg", -360.0, 360.0) * kDegToRad;
      m.arg_lat_rad = sc.get_double(q + "arg_lat_deg", -360.0, 360.0) * kDegToRad;
    }
    f.groups.push_back(gr);
  }
  const std::string ref = sc.get_enum("formation.reference_group", names);
  const std::string tg = sc.get_enum("conjunction.group", names);
  for (std::size_t g = 0; g < ng; ++g) {
    if (names[g] == ref) f.reference_group = g;
    if (names[g] == tg) in.threatened.group = g;
  }
  const std::string role = sc.get_enum("conjunction.satellite", {"chief", "deputy1", "deputy2"});
  in.threatened.role = role == "chief" ? Role::kChief
                                       : (role == "deputy1" ? Role::kDeputy1 : Role::kDeputy2);
  ConjunctionSpec& c = in.conjunction;
  c.tca_s = sc.get_double("conjunction.tca_s", 1.0, 30.0 * kSecondsPerDay);
  c.miss_rsw_m = sc.get_vec3("conjunction.miss_rsw_m", -1e5, 1e5);
  c.v_rel_rsw_mps = sc.get_vec3("conjunction.v_rel_rsw_mps", -2e4, 2e4);
  c.required_miss_m = sc.get_double("conjunction.required_miss_m", 1e-3, 1e5);
  ManeuverTiming& t = in.timing;
  t.burn_before_tca_s = sc.get_double("maneuver.burn_before_tca_s", 1.0, c.tca_s, t.burn_before_tca_s);
  t.restore_after_tca_s =
      sc.get_double("maneuver.restore_after_tca_s", 1.0, 30.0 * kSecondsPerDay, t.restore_after_tca_s);
  t.restore = sc.get_bool("maneuver.restore", t.restore);
  PropagationSettings& ps = in.propagation;
  ps.integrator.rel_tol = sc.get_double("propagation.rel_tol", 1e-14, 1e-6, ps.integrator.rel_tol);
  ps.integrator.abs_tol = sc.get_double("propagation.abs_tol_m", 1e-12, 10.0, ps.integrator.abs_tol);
  ps.samples_per_rev = static_cast<int>(
      sc.get_int("propagation.samples_per_rev", 8, 512, ps.samples_per_rev));
  // Cross-field checks (the same ones the library applies), reported as configuration errors.
  try {
    f.validate();
    c.validate();
    t.validate(c.tca_s);
    ps.validate();
  } catch (const std::invalid_argument& e) {
    throw config::ConfigError(sc.source() + ": " + e.what());
  }
  return in;
}

}  // namespace evade::formation
