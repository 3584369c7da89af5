// A threat-area scenario (paper 001, Yu, Wang, Sun 2017, sec. 4.1: a Tiangong-1-like target
// and an Orbital-Express-like chaser behind it) turned into the solvers' inputs
// (threat::ThreatScenario, threat/threat_study.hpp).
//
// Every key is read through its parameter table (threat_params.hpp) with config::read_params
// and the Earth constants through config::read_earth (WGS-84 defaults; paper 001's μ and Re
// are given by the scenario). target.altitude_m, chaser.dv_max_mps, transfer.dt_s and
// transfer.impulses are required; chaser.relative_rsw_m / relative_rsw_mps are 3-lists.
#pragma once

#include "evade/config/scenario.hpp"
#include "evade/threat/threat_study.hpp"

namespace evade::commands {

/// Reads every key of the command, then rejects any other key but `description`
/// (Scenario::check_all_used). Throws config::ConfigError naming the key, its value and the
/// allowed range (a missing required key is reported as '<missing>').
threat::ThreatScenario read_threat_scenario(const config::Scenario& sc);

}  // namespace evade::commands
