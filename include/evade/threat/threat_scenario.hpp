// A threat-area scenario (paper 001, Yu, Wang, Sun 2017, sec. 4.1: a Tiangong-1-like target
// and an Orbital-Express-like chaser behind it) turned into the solvers' inputs.
//
// Every key is read through its parameter table (threat_params.hpp) with config::read_params
// and the Earth constants through config::read_earth (WGS-84 defaults; paper 001's μ and Re
// are given by the scenario). target.altitude_m, chaser.dv_max_mps, transfer.dt_s and
// transfer.impulses are required; chaser.relative_rsw_m / relative_rsw_mps are 3-lists.
#pragma once

#include "evade/config/scenario.hpp"
#include "evade/core/constants.hpp"
#include "evade/threat/evasion.hpp"
#include "evade/threat/threat_area.hpp"

namespace evade::threat {

/// What a scenario asks the threat-area solvers for.
struct ThreatScenario {
  EarthModel earth;                     ///< earth.* (only μ and Re enter HCW's n)
  ThreatGeometry geometry;              ///< n from the target's circular orbit; chaser at t0
  ThreatOptions threat;                 ///< chaser., transfer., sweep.
  EvasionOptions evasion;               ///< evasion.* (angles in radians)
  double evasion_dv_mps = 20.0;         ///< evasion.dv_mps: V_E of the single optimization
  double elimination_tol_mps = 0.05;    ///< elimination.tol_mps
  double target_inclination_deg = 0.0;  ///< target.inclination_deg (for the record)
};

/// Reads every key of the command, then rejects any other key but `description`
/// (Scenario::check_all_used). Throws config::ConfigError naming the key, its value and the
/// allowed range (a missing required key is reported as '<missing>').
ThreatScenario read_threat_scenario(const config::Scenario& sc);

}  // namespace evade::threat
