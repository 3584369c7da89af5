// Reading screening objects from a scenario (YAML) or from CSV text, with validation that
// names the object's index and the field (issue 6: bad objects are rejected, never
// screened).
//
// YAML: a list `objects`, each item either Keplerian
//   {name, a_m, e, i_deg, raan_deg, argp_deg, mean_anomaly_deg, size_m, pos_error_m}
// or Cartesian {name, r_eci_m: [x,y,z], v_eci_mps: [vx,vy,vz], size_m, pos_error_m},
// given at the scenario epoch (t = 0).
// CSV: a header line naming the columns, then one object per line. Keplerian columns
//   name,a_m,e,i_deg,raan_deg,argp_deg,mean_anomaly_deg,size_m,pos_error_m
// or Cartesian columns
//   name,x_m,y_m,z_m,vx_mps,vy_mps,vz_mps,size_m,pos_error_m
// (any order; '#' lines and blank lines ignored).
#pragma once

#include <string>
#include <vector>

#include "evade/config/scenario.hpp"
#include "evade/conjunction/types.hpp"

namespace evade::commands {

/// Reads `objects.*` from a scenario. Throws config::ConfigError naming the key
/// ("objects.3.e") for a missing, non-finite or out-of-range value, an unbound orbit or a
/// perigee inside the Earth.
std::vector<conjunction::SpaceObject> objects_from_scenario(const config::Scenario& sc, const EarthModel& earth);

/// Parses CSV text (see above). Throws std::invalid_argument naming the line, object index
/// and column for a bad value; then validate_objects() checks the orbits.
std::vector<conjunction::SpaceObject> objects_from_csv(const std::string& text, const EarthModel& earth);

/// Writes events as CSV text (header: i,j,name_i,name_j,tca_s,miss_m,rel_speed_mps,collision,warning).
std::string events_to_csv(const std::vector<conjunction::Conjunction>& events, const std::vector<conjunction::SpaceObject>& objects);

}  // namespace evade::commands
