// Scenario reader for paper 003's planner (see formation_scenario.hpp).
#include "evade/commands/formation_scenario.hpp"

#include <stdexcept>
#include <string>
#include <vector>

#include "evade/config/read_elements.hpp"
#include "evade/config/read_params.hpp"

namespace evade::commands {
namespace {

// Required rows first (a missing key is named), then every row, checked.
template <class Cfg>
void read_formation_table(const config::Scenario& sc, const std::string& prefix,
                const ParamTable<Cfg>& table, Cfg* cfg) {
  config::require_params(sc, prefix, table, *cfg);
  config::read_params(sc, prefix, table, cfg);
}

void read_formation_scalars(const config::Scenario& sc, formation::FormationSpec& f) {
  formation::FormationParams p;
  read_formation_table(sc, "formation.", formation::formation_params(), &p);
  if (p.box_delta_m > p.side_length_m / 8.0) {
    throw config::ConfigError(
        sc.source() + ": key 'formation.box_delta_m' = '" + param_value_text(p.box_delta_m) +
        "' is invalid: expected at most formation.side_length_m / 8 = " +
        param_value_text(p.side_length_m / 8.0) + " m");
  }
  f.side_length_m = p.side_length_m;
  f.box_delta_m = p.box_delta_m;
  f.raan_tolerance_rad = p.raan_tolerance_deg * kDegToRad;
  f.phase_tolerance_rad = p.phase_tolerance_deg * kDegToRad;
  f.horizon_days = p.horizon_days;
}

// formation.groups.N: unique names, nominal offsets and the three satellites' elements.
std::vector<std::string> read_groups(const config::Scenario& sc, formation::FormationSpec& f) {
  const std::size_t ng = sc.list_size("formation.groups");
  if (ng < 2) {
    throw config::ConfigError(sc.source() + ": key 'formation.groups' has " + std::to_string(ng) +
                              " groups; allowed: a list of at least 2 (a reference and another)");
  }
  const char* roles[3] = {"chief", "deputy1", "deputy2"};
  std::vector<std::string> names;
  for (std::size_t g = 0; g < ng; ++g) {
    const std::string p = "formation.groups." + std::to_string(g) + ".";
    formation::Group gr;
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
      // The one element reader and its limits; the near-circular model's tighter limits
      // (e <= 0.01, a from re_m + 100 km, i away from 0 and 180 deg) are
      // FormationSpec::validate()'s, reported with their reason by read_plan_inputs.
      const OrbitalElements oe =
          config::read_elements(sc, q, f.earth, config::OrbitPhase::kArgumentOfLatitude);
      formation::MeanElements& m = gr.sats[static_cast<std::size_t>(r)];
      m.a_m = oe.a_m;
      m.e = oe.e;
      m.i_rad = oe.i_rad;
      m.raan_rad = oe.raan_rad;
      m.arg_lat_rad = oe.true_anomaly_rad;  // this form reads u as the true anomaly, argp = 0
    }
    f.groups.push_back(gr);
  }
  return names;
}

// The reference group and the threatened satellite, by name.
void read_names(const config::Scenario& sc, const std::vector<std::string>& names,
                formation::PlanInputs& in) {
  const std::string ref = sc.get_enum("formation.reference_group", names);
  const std::string tg = sc.get_enum("conjunction.group", names);
  for (std::size_t g = 0; g < names.size(); ++g) {
    if (names[g] == ref) in.spec.reference_group = g;
    if (names[g] == tg) in.threatened.group = g;
  }
  const std::string role = sc.get_enum("conjunction.satellite", {"chief", "deputy1", "deputy2"});
  in.threatened.role = role == "chief" ? formation::Role::kChief
                                       : (role == "deputy1" ? formation::Role::kDeputy1 : formation::Role::kDeputy2);
}

}  // namespace

formation::PlanInputs read_plan_inputs(const config::Scenario& sc) {
  formation::PlanInputs in;
  formation::FormationSpec& f = in.spec;
  f.earth = config::read_earth(sc);
  read_formation_scalars(sc, f);
  const std::vector<std::string> names = read_groups(sc, f);
  read_names(sc, names, in);
  formation::ConjunctionSpec& c = in.conjunction;
  read_formation_table(sc, "conjunction.", formation::conjunction_spec_params(), &c);
  c.miss_rsw_m = sc.get_vec3("conjunction.miss_rsw_m", -1e5, 1e5);
  c.v_rel_rsw_mps = sc.get_vec3("conjunction.v_rel_rsw_mps", -2e4, 2e4);
  read_formation_table(sc, "maneuver.", formation::maneuver_timing_params(), &in.timing);
  formation::PropagationParams pp;
  read_formation_table(sc, "propagation.", formation::propagation_params(), &pp);
  in.propagation.integrator.rel_tol = pp.rel_tol;
  in.propagation.integrator.abs_tol = pp.abs_tol_m;
  in.propagation.samples_per_rev = pp.samples_per_rev;
  // Cross-field checks (the same ones the library applies), reported as configuration errors.
  try {
    f.validate();
    c.validate();
    in.timing.validate(c.tca_s);
    in.propagation.validate();
  } catch (const std::invalid_argument& e) {
    throw config::ConfigError(sc.source() + ": " + e.what());
  }
  return in;
}

}  // namespace evade::commands
