// `evade plan threat-area` as a library call (paper 001: Yu Dateng, Wang Hua, Sun Fuyu,
// "Optimal evasive maneuver strategy with potential threatening area being considered",
// Acta Aeronautica et Astronautica Sinica, 2017): the chaser's potential threat area
// (sec. 2.2), the target's optimal evasive burn direction at fixed V_E (sec. 3), the
// smallest eliminating burn (sec. 4.2, Fig. 8 / Table 3) and the transfer-time study
// (Fig. 4). Request -> run -> result; to_json is the command's JSON (the keys and number
// formatting of `evade plan threat-area --json`), to_text its human report.
// The burn is one impulse at t0 (the scenario's t = 0); its direction is pitch α and yaw θ in
// the target's VVLH frame (evasion.hpp), its Δv given in VVLH and in RSW.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "evade/config/scenario.hpp"
#include "evade/commands/threat_scenario.hpp"
#include "evade/threat/threat_study.hpp"

namespace evade::commands {

struct ThreatAreaRequest {
  std::string scenario_source;  ///< the scenario's name or path (echoed as "scenario")
  nlohmann::json scenario_used = nlohmann::json::object();  ///< every scenario value read
  threat::ThreatScenario scenario;      ///< the solvers' inputs (flags may override them)
  threat::ThreatStudyRequest study;     ///< elimination, V_E sweep, transfer-time sweep
  threat::ThreatStudyProgress progress; ///< optional hooks called as each step starts or ends
};

/// Reads every key of the command (read_threat_scenario: parameter tables, Earth table,
/// check_all_used). Throws config::ConfigError naming the key, its value and the range.
ThreatAreaRequest read_threat_area_request(const config::Scenario& sc);

struct ThreatAreaResult {
  std::string scenario_source;
  nlohmann::json scenario_used = nlohmann::json::object();
  threat::ThreatScenario scenario;  ///< the inputs the study ran with
  threat::ThreatStudy study;        ///< every figure (costs, burn, arcs, sweeps, wall times)
};

/// Runs the study (run_threat_study). Throws std::invalid_argument for bad inputs (naming the
/// field) and std::runtime_error if an elimination search finds no eliminating V_E.
ThreatAreaResult run_threat_area(const ThreatAreaRequest& req);

/// The JSON of `evade plan threat-area --json` (same keys, order and numbers).
nlohmann::json to_json(const ThreatAreaResult& r);

/// The human report: inputs, the chaser's cost at t0, the burn (α, θ in VVLH; Δv in VVLH and
/// RSW, m/s, at t0), the threat arc and its intervals (s after t0), the search certificate,
/// the eliminating burn and the sweep rows when asked for.
std::string to_text(const ThreatAreaResult& r);

}  // namespace evade::commands
