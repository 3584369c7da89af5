// `evade assess` as a library call: the collision probability of one conjunction given as
// the states of both objects (a scenario's `conjunction:` block or a CCSDS CDM, brought to
// TCA and assessed by assess.hpp) or as the encounter plane directly (miss and sigmas along
// its principal axes). The request says where the encounter comes from; the result holds
// every figure the command prints, its JSON form (to_json, the CLI's --json output) and its
// text form (to_text). Methods (pc_2d.hpp, monte_carlo_pc.hpp): the 2D Pc of the short-term
// encounter model (Foster & Estes 1992, NASA JSC-25898), Chan's series (Chan 2008,
// "Spacecraft Collision Probability", eq. 5.33), Alfano's maximum Pc (Alfano 2005, "Relating
// Position Uncertainty to Maximum Conjunction Probability") and, on request, the Monte Carlo
// Pc (Alfano 2009, "Satellite Conjunction Monte Carlo Analysis"); the short-term validity
// test of Chan 2008 ch. 4 and Alfano 2009.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evade/assessment/assess.hpp"
#include "evade/ccsds/cdm.hpp"
#include "evade/assessment/pc_method_choice.hpp"
#include "evade/config/scenario.hpp"

namespace evade::commands {

struct AssessRequest {
  std::string source;  ///< how the result names its input ("scenario NAME", "cdm NAME", ...)
  assessment::AssessConfig config;  ///< the assessment.* parameter table
  /// Both objects' states and covariances (from a scenario or a CDM); or else
  std::optional<assessment::ConjunctionInput> conjunction;
  /// the encounter plane given directly (no states: no TCA, covariance or short-term checks).
  std::optional<assessment::PrincipalEncounter> encounter_plane;
  double plane_hbr_m = 0.0;    ///< hard-body radius with encounter_plane [m]
  std::optional<ccsds::Cdm> cdm;      ///< the message the states came from: its own figures reported
  long mc_samples = 0;         ///< Monte Carlo samples (states only); 0: no Monte Carlo
  std::uint64_t mc_seed = 1;   ///< Monte Carlo seed
  assessment::McExecution mc_exec;         ///< how a Monte Carlo runs (threads; MPI ranks)
};

/// From a scenario's `conjunction:` block and its assessment.* table; every key of sc must
/// have been read (config::ConfigError names the first that was not, or a bad value).
AssessRequest read_assess_request(const config::Scenario& sc);
/// From a CDM's text (KVN or XML; CdmError for a malformed one), named cdm_name in the result;
/// hbr_m <= 0: from AREA_PC of both objects (std::invalid_argument when absent). The
/// assessment.* table and the Earth model come from sc (an empty scenario with overrides).
AssessRequest read_assess_request_cdm(const config::Scenario& sc, const std::string& cdm_text,
                                      const std::string& cdm_name, double hbr_m);
/// The encounter plane given directly, named "encounter plane".
AssessRequest encounter_plane_request(const assessment::PrincipalEncounter& plane, double hbr_m);

/// The message's own relative figures, beside those recomputed from its states.
struct CdmFigures {
  std::string message_id;
  std::string tca_utc;                                ///< TCA as the message writes it (UTC)
  std::optional<double> miss_distance_m;              ///< none when the message has none
  std::optional<double> relative_speed_mps;
  std::optional<double> collision_probability;
  std::optional<std::string> collision_probability_method;
  std::vector<std::string> unit_notes;  ///< units read as the standard's equivalent spelling,
                                        ///< and each 7x7..9x9 covariance not positive definite
};

/// What only an assessment from states has.
struct StatesAtTca {
  /// The states and covariances used (after the TCA shift and any repair).
  std::array<assessment::ObjectState, 2> at_tca;
  double tca_shift_s = 0.0;           ///< TCA minus the epoch of the given states [s]
  std::string tca_method;             ///< how the states were brought to TCA
  std::string covariance_propagation;
  std::array<bool, 2> covariance_repaired = {false, false};  ///< by eigenvalue clipping
  std::array<double, 2> covariance_min_eigenvalue_m2 = {0.0, 0.0};
  assessment::EncounterPlane plane;  ///< miss and combined covariance in the encounter frame
  assessment::ShortTermCheck short_term;
};

struct AssessResult {
  std::string source;
  double hbr_m = 0.0;
  double miss_m = 0.0;                  ///< at TCA (states) or in the plane given [m]
  std::optional<double> rel_speed_mps;  ///< at TCA; none for an encounter plane given directly
  assessment::PrincipalEncounter principal;  ///< miss and sigmas along the plane's principal axes
  /// The Pc of every plane method (assessment/pc_methods.hpp), in table order. The escalation's
  /// steps (3D-Nc, Monte Carlo) are in choice; a new method is a row of the table, and its Pc
  /// and figures reach the JSON and the text from there.
  std::vector<assessment::PcValue> plane_pc;
  /// The Monte Carlo's details: with mc_samples > 0, or run by the escalation.
  std::optional<assessment::MonteCarloResult> pc_mc;
  double pc = 0.0;            ///< the recommended Pc (pc_method_choice.hpp)
  std::string method = "2d";  ///< the method that produced it: "2d", "3d_nc" or "mc"
  std::optional<assessment::PcChoice> choice;  ///< from states: the steps and their checks
  int mc_ranks = 1;                   ///< MPI ranks the Monte Carlo ran on
  std::optional<StatesAtTca> states;  ///< from states only
  std::optional<CdmFigures> cdm;      ///< from a CDM only
};

/// Throws std::invalid_argument for bad input (as assess does; Monte Carlo without states;
/// no encounter given).
AssessResult run_assess(const AssessRequest& req);

/// The CLI's --json output: miss_m, rel_speed_mps, every method's "pc_<name>" and
/// "pc_<name>_<figure>" (pc_methods.hpp: pc_2d, pc_chan, pc_max, pc_max_scale; from states
/// also pc_2d_abs_error, pc_3d_nc, pc_mc with pc_mc_low and pc_mc_high), encounter_plane, and
/// from states tca, covariance checks, short_term, the usage checks of each escalation step
/// and the details of 3D-Nc (nc3d) and the Monte Carlo (mc), cdm and notes with a CDM.
nlohmann::json to_json(const AssessResult& r);
/// The text output: miss, HBR, every Pc, the short-term verdict, each covariance repair and
/// each CDM unit note.
std::string to_text(const AssessResult& r);
/// What a user must not miss, one line each (the CLI prints them on stderr too): each
/// covariance repaired before the Pc, and each CDM unit note ("note: ...").
std::vector<std::string> assess_warnings(const AssessResult& r);

}  // namespace evade::commands
