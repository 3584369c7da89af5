// `evade cam review` as a library call (docs/AUTONOMY.md AUT-10; NASA Starling 1.5's screening
// of a proposed burn before it is flown): the node's proposed avoidance burn (its
// evade_cam_proposal_t: burn time and delta-v in ECI) applied to the own spacecraft of the
// event's CDM (OBJECT1 at TCA, carried back to the burn under two-body + J2), and both orbits,
// with and without the burn, screened against an SGP4 catalog by the robust screener
// (conjunction::OwnOrbitMotion: the own spacecraft on its own force model beside the
// catalog's SGP4) from the burn over span_s. A catalog carries no covariances, so each close
// approach is weighed by its maximum Pc over every circular covariance (S. Alfano, "Relating
// position uncertainty to maximum conjunction probability", 2005: the
// largest probability a miss of that size can have, R^2 / (e d^2) for d >> R), against the
// event's red threshold. The review recommends a veto when the burn creates, or raises, a
// close approach whose maximum Pc is above the red threshold; otherwise the burn may fly.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evade/assessment/assess.hpp"
#include "evade/core/param.hpp"
#include "evade/core/state.hpp"
#include "evade/sgp4/catalog.hpp"

namespace evade::commands {

/// What the review takes of the node's proposal.
struct CamReviewProposal {
  std::int64_t event_id = 0;
  std::int32_t version = 0;
  std::int64_t proposal_id = 0;
  std::int64_t burn_utime = 0;        ///< burn (impulse centre), Unix time [us]
  Vec3 dv_eci_mps = Vec3::Zero();     ///< its delta-v, ECI (J2000 axes) [m/s]
};
/// From the JSON `evade cam review --json` prints as its "proposal" (event_id, version,
/// proposal_id, burn_utime, dv_eci_mps [3]); std::invalid_argument naming the key.
CamReviewProposal cam_review_proposal_from_json(const nlohmann::json& j, const std::string& name);
nlohmann::json to_json(const CamReviewProposal& p);

struct CamReviewRequest {
  CamReviewProposal proposal;
  assessment::ConjunctionInput conjunction;  ///< the event's CDM: OBJECT1 is the own spacecraft
  double tca_j2000_s = 0.0;                  ///< its TCA, UTC s since J2000
  std::string own_designator;                ///< OBJECT1's designator: left out of the catalog
  sgp4::Catalog catalog;
  std::string catalog_source;
  double pc_red = 1e-4;       ///< the event's red threshold [-]
  double span_s = 86400.0;    ///< screened from the burn, (0, 7 d]; must reach past TCA [s]
  double threshold_m = 5000.0;  ///< close approaches reported within [m]
  int threads = 0;            ///< 0: every core
};

/// One catalog object's closest approach to the own spacecraft, with and without the burn.
struct CamReviewEncounter {
  long norad_id = 0;
  std::string name;
  bool before = false, after = false;  ///< within the threshold without / with the burn
  double miss_before_m = 0.0, miss_after_m = 0.0;
  double tca_after_s = 0.0;            ///< from the burn [s] (with the burn; else without)
  std::string tca_utc;
  double pc_max_before = 0.0, pc_max_after = 0.0;
  bool raised = false;                 ///< pc_max_after > pc_red and > pc_max_before
};

struct CamReviewResult {
  std::string verdict;  ///< "veto" or "fly"
  std::string reason;
  CamReviewProposal proposal;
  std::string burn_utc;
  double span_s = 0.0, threshold_m = 0.0, pc_red = 0.0, hbr_m = 0.0;
  long objects = 0, rejected = 0;
  double own_perturbation_mps2 = 0.0;  ///< the own orbit's bound against the screener's field
  std::vector<CamReviewEncounter> encounters;  ///< by miss with the burn
};

/// The request of the event's CDM text (KVN or XML; its conjunction as evade assess --cdm reads
/// it, hbr_m <= 0: from AREA_PC), the proposal and the catalog; the flags' typed values
/// (`--pc-red` uplink.pc_red, `--span-s` span_s, `--threshold-m` robust.threshold_m; any other
/// key: config::ConfigError) set the rest.
CamReviewRequest read_cam_review_request(const std::string& cdm_text, const std::string& cdm_name,
                                         double hbr_m, const CamReviewProposal& proposal,
                                         sgp4::Catalog catalog, const std::string& catalog_source,
                                         const std::vector<ParamValue>& values);

/// Throws std::invalid_argument for a burn not before TCA, a span that ends before TCA, or a
/// catalog with no usable element set.
CamReviewResult run_cam_review(const CamReviewRequest& req);
nlohmann::json to_json(const CamReviewResult& r);
std::string to_text(const CamReviewResult& r);

/// The largest Pc a miss of miss_m can have over every circular covariance, hard-body radius
/// hbr_m (1 when the miss is inside the radius).
double pc_max_circular(double miss_m, double hbr_m);

}  // namespace evade::commands
