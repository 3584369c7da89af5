// Scenario → threat-area solver inputs (include/evade/commands/threat_scenario.hpp). Paper 001
// (Yu, Wang, Sun 2017) sec. 4.1: the target on a circular orbit (mean motion n of the HCW
// model, sec. 2.1 eq. 1), the chaser's relative state at t0, ΔV_max and ΔT; sec. 3.2 and
// 4.2: the evasion search and the eliminating burn. Keys and ranges: threat_params.cpp.
#include "evade/commands/threat_scenario.hpp"

#include <string>

#include "evade/config/read_params.hpp"
#include "evade/core/param.hpp"
#include "evade/threat/threat_params.hpp"

namespace evade::commands {
namespace {

// Keys without a usable default: the problem is not defined without them.
const char* const kRequiredKeys[] = {"target.altitude_m", "chaser.dv_max_mps", "transfer.dt_s",
                                     "transfer.impulses"};

// Throws ConfigError for a required key of `table` that the scenario does not give.
template <class Cfg>
void require_keys(const config::Scenario& sc, const ParamTable<Cfg>& table) {
  for (const Param<Cfg>& p : table) {
    for (const char* key : kRequiredKeys) {
      if (p.spec.key == std::string(key) && !sc.has(key)) {
        throw config::ConfigError(sc.source() + ": " + param_error(key, "<missing>", p.spec) +
                                  " (required key)");
      }
    }
  }
}

// Reads `table` (prefix "": its keys carry their section) into a default Cfg.
template <class Cfg>
Cfg read_threat_table(const config::Scenario& sc, const ParamTable<Cfg>& table) {
  require_keys(sc, table);
  Cfg cfg;
  config::read_params(sc, "", table, &cfg);
  return cfg;
}

}  // namespace

threat::ThreatScenario read_threat_scenario(const config::Scenario& sc) {
  threat::ThreatScenario out;
  out.earth = config::read_earth(sc);
  const auto geometry = read_threat_table(sc, threat::threat_geometry_params());
  Vec6 chaser0_rsw;
  chaser0_rsw << sc.get_vec3("chaser.relative_rsw_m", -1e8, 1e8),
      sc.get_vec3("chaser.relative_rsw_mps", -1e4, 1e4);
  const auto options = read_threat_table(sc, threat::threat_option_params());
  const auto evasion = read_threat_table(sc, threat::evasion_params());
  sc.mark_used("description");
  sc.check_all_used();

  out.geometry = geometry.geometry(out.earth, chaser0_rsw);
  out.target_inclination_deg = geometry.target.inclination_deg;
  out.threat = options.options();
  out.evasion = evasion.options();
  out.evasion_dv_mps = evasion.evasion.dv_mps;
  out.elimination_tol_mps = evasion.elimination.tol_mps;
  return out;
}

}  // namespace evade::commands
