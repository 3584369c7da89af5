// `evade propagate` as a library call: the foundation demo. Propagates one orbit with the
// chosen gravity model (two-body, or two-body + J2 integrated with DOP853) and reports the
// final state, the RAAN change, and for J2 the analytic secular rate's prediction (Vallado,
// "Fundamentals of Astrodynamics and Applications", 4th ed., 2013, eq. 9-41, 9-42) beside the
// numerically observed drift, and the displacement from the pure two-body orbit.
//
// Scenario keys: epoch_utc, earth.* (config::read_earth), orbit.* (the one element reader,
// config/read_elements.hpp, true-anomaly form), propagation.model (two-body | two-body-j2)
// and the numbers of propagate_params() under "propagation.".
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "evade/config/scenario.hpp"
#include "evade/core/constants.hpp"
#include "evade/core/elements.hpp"
#include "evade/core/epoch.hpp"
#include "evade/core/param.hpp"
#include "evade/core/state.hpp"
#include "evade/dynamics/dop853.hpp"
#include "evade/dynamics/gravity.hpp"

namespace evade::commands {

/// The run's numbers (scenario keys propagation.<key>). duration_s has no default.
struct PropagateParams {
  double duration_s = 0.0;  ///< propagation time span [s] (required)
  double rel_tol = AdaptiveOptions{}.rel_tol;  ///< DOP853 relative tolerance [-]
  double abs_tol = AdaptiveOptions{}.abs_tol;  ///< DOP853 absolute tolerance [m and m/s]
};
/// The table of PropagateParams (key, unit, range, meaning), prefix "propagation.".
ParamTable<PropagateParams> propagate_params() noexcept;

struct PropagateRequest {
  CalendarUtc epoch_utc;                 ///< epoch of the initial elements (UTC)
  EarthModel earth = kEarthDefault;
  OrbitalElements initial_elements;      ///< osculating, ECI (J2000), at epoch_utc
  GravityModel model = GravityModel::kTwoBodyJ2;
  PropagateParams params;
  nlohmann::json parameters = nlohmann::json::object();  ///< scenario values used, echoed
};

/// Every input from the scenario, checked; then sc.check_all_used(). Throws
/// config::ConfigError (or std::invalid_argument for a malformed epoch_utc).
PropagateRequest read_propagate_request(const config::Scenario& sc);

struct PropagateResult {
  CalendarUtc epoch_utc;                  ///< start (UTC)
  CalendarUtc end_utc;                    ///< epoch + duration (UTC)
  double duration_s = 0.0;
  GravityModel model = GravityModel::kTwoBodyJ2;
  StateEci final_eci;                     ///< final state with the chosen model (ECI J2000)
  double delta_raan_deg = 0.0;            ///< osculating RAAN change, wrapped to [-180, 180)
  double secular_delta_raan_deg = 0.0;    ///< J2 secular prediction over the span (0: two-body)
  double j2_displacement_from_kepler_m = 0.0;  ///< |r - r_two-body| at the end [m]
  IntegrationStats stats;                 ///< DOP853 steps (zero for two-body: analytic)
  double runtime_s = 0.0;                 ///< wall-clock time of the propagation [s]
  nlohmann::json parameters = nlohmann::json::object();
};

/// "two-body" or "two-body-j2" (the scenario's and the JSON's name).
const char* gravity_model_name(GravityModel model);

/// Propagates the request's orbit. Throws std::invalid_argument for elements outside the
/// element limits, std::runtime_error if the integration fails.
PropagateResult run_propagate(const PropagateRequest& req);

/// The JSON `evade propagate --json` prints.
nlohmann::json to_json(const PropagateResult& r);
/// The text `evade propagate` prints.
std::string to_text(const PropagateResult& r);

}  // namespace evade::commands
