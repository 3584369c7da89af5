// `evade plan cam` as a library call: the minimum-Δv collision-avoidance burn of the primary
// (object1), made lead_s before TCA, after which Pc < pc_max and the miss > min_miss_m
// (cam_planner.hpp: encounter-plane reduction, NLopt SLSQP (Kraft 1988), re-linearisation,
// verified by two-body + J2 propagation), or the trade space of that burn over a range of
// lead times. The conjunction comes from a scenario's `conjunction:` block or a CCSDS CDM;
// a CDM also gives the UTC of its states (its TCA), and so the burn's UTC. The result holds
// every figure the command prints, its JSON form (to_json, the CLI's --json output) and its
// text form (to_text: the plan, or the trade space as CSV).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evade/cam/cam_planner.hpp"
#include "evade/assessment/pc_method_choice.hpp"
#include "evade/config/scenario.hpp"

namespace evade::commands {

/// Lead times from first_lead_s to last_lead_s, count of them evenly spaced (count 1: the
/// first only).
struct CamLeadSweep {
  double first_lead_s = 0.0;
  double last_lead_s = 0.0;
  int count = 1;  ///< in [1, 10000]
};

struct PlanCamRequest {
  std::string source;             ///< how the result names its input ("scenario NAME", ...)
  assessment::ConjunctionInput conjunction;   ///< both objects' states and covariances
  assessment::AssessConfig assess_config;     ///< the assessment.* parameter table
  cam::CamConfig cam_config;           ///< the cam.* parameter table
  /// UTC of the given states [s since J2000] (a CDM's TCA); a scenario has none.
  std::optional<double> epoch_utc_j2000_s;
  cam::CamRequest cam;                 ///< lead_s, pc_max, min_miss_m, along_track_only
  std::optional<CamLeadSweep> sweep;  ///< the trade space over lead times instead of cam.lead_s
};

/// From a scenario's `conjunction:` block and its assessment.* and cam.* tables; every key of
/// sc must have been read (config::ConfigError names the first that was not, or a bad value).
/// The planner's request (cam) is left at its defaults for the caller to fill.
PlanCamRequest read_plan_cam_request(const config::Scenario& sc);
/// From a CDM's text (KVN or XML; CdmError for a malformed one), named cdm_name in the result;
/// hbr_m <= 0: from AREA_PC of both objects (std::invalid_argument when absent). The tables
/// and the Earth model come from sc (an empty scenario with overrides).
PlanCamRequest read_plan_cam_request_cdm(const config::Scenario& sc, const std::string& cdm_text,
                                         const std::string& cdm_name, double hbr_m);

struct PlanCamResult {
  std::string source;
  cam::CamRequest request;  ///< as asked (lead_s unused with a sweep)
  std::optional<double> epoch_utc_j2000_s;  ///< UTC of the given states, when known
  /// One lead time: the plan, with the burn's UTC [s since J2000] and as a Unix utime [us]
  /// when the states' UTC is known.
  std::optional<cam::CamPlan> plan;
  std::optional<double> burn_utc_j2000_s;
  std::optional<std::int64_t> burn_unix_utime_us;
  std::vector<cam::CamSweepRow> sweep;  ///< with a sweep request: one row per lead time
  /// The recommended Pc before the burn (pc_method_choice.hpp) and its method. The planner's
  /// model is the 2D Pc; the need for a burn and its verification use the recommended Pc
  /// (CamPlan::before_recommended, verified_recommended; cam_planner.hpp).
  double pc_before_recommended = 0.0;
  std::string pc_method_before = "2d";
  std::string pc_method_reason;
};

/// Throws std::invalid_argument for a bad request (either end of a sweep too) or input, and
/// when one lead time's threshold cannot be reached (a sweep reports it in its row).
PlanCamResult run_plan_cam(const PlanCamRequest& req);

/// The CLI's --json output: the plan (Δv in RTN and ECI, before, predicted, verified, the
/// burn's UTC when known, frames) and source; with a sweep, the request and one row per lead.
nlohmann::json to_json(const PlanCamResult& r);
/// The text output: the plan (burn lead and UTC, Δv with its frames and unit, Pc and miss
/// before, predicted and verified); with a sweep, the trade space as CSV.
std::string to_text(const PlanCamResult& r);

}  // namespace evade::commands
