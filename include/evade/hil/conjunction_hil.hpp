// The onboard conjunction response end to end in the HIL (docs/AUTONOMY.md AUT-11; `evade cam
// hil`, scripts/conjunction_demo): the simulator flies a LEO primary (the node's spacecraft)
// and a secondary on a collision course about 1.5 orbits ahead under two-body + J2 truth,
// lockstep against evade_guidance_node over LCM; the ground side builds each CCSDS CDM from
// the simulator's truth at TCA plus the covariances below (commands::cdm_from_event), reads it
// back as `evade conjunction` does (commands::read_conjunction_uplink) and uplinks it signed
// (lcm_link::uplink_conjunction, stamped with the simulator's tick time, the node's clock in
// lockstep); it vetoes the node's proposal when the run asks for that
// (lcm_link::uplink_cam_decision). Every signed proposal the node publishes is verified and
// recorded; the truth's miss at the new TCA, the post-burn Pc there (the 2D Pc of the
// uplinked covariances on the truth's states, assessment::assess_encounter_2d), the delivered
// Δv and the timeline are reported.
//
// Three runs:
//  - burn:   one CDM 60 s into the run; the node proposes, the veto deadline passes, it burns.
//  - veto:   the same, and the ground vetoes the proposal as soon as it sees it: no burn.
//  - update: the first CDM places the secondary update_offset_m off its true path (stale
//            tracking, like a third party's manoeuvre the ground has not yet seen): no action;
//            a new version from the truth update_lead_s before TCA, with a shorter veto
//            deadline, changes the answer: the node proposes and burns.
// Ground and test code: allocates, throws.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evade/commands/conjunction_uplink_command.hpp"
#include "evade/core/param.hpp"
#include "evade/lcm_link/command_uplink.hpp"
#include "evade/sim/plan_run.hpp"

namespace evade::hil {

/// The case (key prefix "hil."): geometry, covariances and the ground's timing.
struct ConjunctionHilConfig {
  double altitude_m = 550e3;          ///< primary's circular orbit above the equatorial radius [m]
  double inclination_deg = 53.0;      ///< its inclination [deg]
  double orbits_to_tca = 1.5;         ///< TCA this many primary periods after the run starts [-]
  double miss_m = 50.0;               ///< the truth's miss at TCA without a burn [m]
  double crossing_deg = 60.0;         ///< angle between the two velocities at TCA [deg]
  double hbr_m = 10.0;                ///< combined hard-body radius [m]
  double own_sigma_m = 20.0;          ///< primary's radial position sigma (along-track 3x, normal 0.5x) [m]
  double other_sigma_m = 100.0;       ///< secondary's radial position sigma (same shape) [m]
  double first_cdm_s = 60.0;          ///< the first CDM is sent this long after the run starts [s]
  double update_lead_s = 3600.0;  ///< run update: the new version is sent this long before TCA [s]
  double update_offset_m = 9000.0;    ///< run update: the first CDM's secondary this far off its truth [m]
  double update_veto_deadline_before_tca_s = 2400.0;  ///< run update: the new version's veto deadline [s]
  double after_tca_s = 60.0;          ///< the run ends this long after TCA [s]
  double rate_hz = 50.0;              ///< the exchange rate: the node's guidance.rate_hz [Hz]
};
ParamTable<ConjunctionHilConfig> conjunction_hil_params() noexcept;

enum class HilRun : std::uint8_t { kBurn = 0, kVeto = 1, kUpdate = 2 };
/// "burn", "veto", "update"; false for another name.
bool parse_hil_run(const std::string& name, HilRun* out) noexcept;
const char* hil_run_name(HilRun r) noexcept;

/// One CDM the ground sends: when, its text and the event read back from it.
struct HilCdm {
  double t_send_s = 0.0;             ///< from the run's start [s]
  std::string file_name;             ///< "<MESSAGE_ID>.cdm"
  std::string text;                  ///< KVN
  commands::ConjunctionUplink uplink;  ///< as `evade conjunction --cdm` reads it at t_send_s
  double miss_m = 0.0;               ///< the CDM's miss at its TCA [m]
  double pc = 0.0;                   ///< its COLLISION_PROBABILITY [-]
  std::string pc_method;
};

struct ConjunctionHilCase {
  HilRun run = HilRun::kBurn;
  ConjunctionHilConfig config;
  sim::PlanRunConfig sim;            ///< both objects at t = 0, utime0_us a calendar time
  double tca_s = 0.0;                ///< from the run's start [s]
  StateEci own_tca, other_tca;       ///< the truth at TCA without a burn (ECI = EME2000 axes)
  std::vector<HilCdm> cdms;          ///< in sending order
  bool veto = false;                 ///< the ground vetoes the node's proposal
};

/// The case of one run: hil.* and uplink.* settings (typed, as flags give them; uplink.* as
/// `evade conjunction` takes them, the update's new version with
/// hil.update_veto_deadline_before_tca_s). Throws config::ConfigError for a bad setting and
/// std::invalid_argument naming the key for a case that cannot be built.
ConjunctionHilCase conjunction_hil_case(HilRun run, const std::vector<ParamValue>& settings);

/// The link to the node for a run.
struct HilLinkOptions {
  std::string lcm_url;
  std::string sensor_key_file;   ///< signs nav and the sim clock (empty: unsigned sensors)
  std::int32_t sensor_key_id = 0;
  double lcm_timeout_s = 10.0;   ///< lockstep: the node's command must come within this [s]
  lcm_link::UplinkOptions uplink;  ///< the ground's commands (clock_utime set by the run)
};

/// A ground command as sent and answered.
struct HilUplink {
  std::string what;       ///< "conjunction v<N> (<file>)" or "veto of proposal <P>"
  std::int32_t version = 0;  ///< the conjunction's version (0: a decision)
  double t_sent_s = 0.0;  ///< simulator time of the first transmission [s]
  double t_answered_s = 0.0;  ///< simulator time when the answer was seen (cycle resolution) [s]
  lcm_link::UplinkResult result;
};

/// A verified evade_cam_proposal_t whose state, reason, version or proposal changed.
struct HilProposal {
  double t_s = 0.0;  ///< the node's cycle time, from the run's start [s]
  nlohmann::json message;  ///< its fields (lcm_link::watch_proposal's names)
};

struct ConjunctionHilRun {
  sim::PlanRunResult sim;
  std::vector<HilUplink> uplinks;
  std::vector<HilProposal> proposals;
  int proposals_verified = 0;
  int proposals_ignored = 0;
  double wall_s = 0.0;  ///< the run's wall-clock time [s]
};

/// Flies the case lockstep against the node at o.lcm_url, the ground's commands signed with
/// keys and counted by arsn. Throws std::runtime_error when LCM fails, the node stops
/// answering, or a ground command gets no answer.
ConjunctionHilRun run_conjunction_hil(const ConjunctionHilCase& c, const HilLinkOptions& o,
                                      const lcm_link::GroundKeys& keys, lcm_link::ArsnSource* arsn);

/// The truth's closest approach from the run's samples around TCA (relative motion linear
/// within a cycle): the time from the run's start [s] and the miss [m].
struct HilClosest {
  double t_s = 0.0;
  double miss_m = 0.0;
  StateEci own, other;  ///< at the sample nearest the closest approach
};
HilClosest hil_closest_approach(const sim::PlanRunResult& r);

/// What `evade cam hil --json` prints: the case, the CDMs, the uplinks and their answers, the
/// proposals' timeline, the burns delivered, the truth's miss and Pc at the new TCA beside the
/// thresholds, and the decision latency (receipt to proposal, simulator time).
nlohmann::json to_json(const ConjunctionHilCase& c, const ConjunctionHilRun& r);

}  // namespace evade::hil
