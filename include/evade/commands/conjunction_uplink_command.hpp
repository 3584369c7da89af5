// `evade conjunction` as a library call (docs/AUTONOMY.md AUT-1): the onboard response's event
// from a CCSDS CDM, as the ground uplinks it. Both objects' states and covariances at TCA
// (commands::conjunction_from_cdm, the reader of `evade assess --cdm` and `evade plan cam
// --cdm`: RTN covariances turned into ECI, J2000 axes; REF_FRAME ITRF refused), the combined
// hard-body radius (--hbr-m, or AREA_PC of both objects), TCA as the node's Unix utime, and the
// operator's settings (uplink.* below): the red threshold and the post-burn target, the burn
// window and the veto deadline as times before TCA. The event id and version come from the
// message when not given: the id from the two objects' designators (one pair of objects, one
// event), the version from its CREATION_DATE (a newer message of the pair replaces the older
// one on the node). The event is checked as the node checks it (autonomy::check_event) before
// anything is sent; a problem is an error naming the flag or the CDM keyword.
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "evade/autonomy/conjunction_event.hpp"
#include "evade/config/scenario.hpp"
#include "evade/core/param.hpp"

namespace evade::commands {

/// The operator's settings of an uplinked conjunction (key prefix "uplink.").
struct ConjunctionUplinkConfig {
  double pc_red = 1e-4;                       ///< above it the event needs a burn [-]
  double pc_target = 1e-5;                    ///< the burn brings the Pc below it [-]
  double window_open_before_tca_s = 21600.0;  ///< the node may burn from TCA minus this... [s]
  double window_close_before_tca_s = 600.0;   ///< ...to TCA minus this [s]
  double veto_deadline_before_tca_s = 7200.0; ///< the ground's veto counts until TCA minus this [s]
  int event_id = 0;       ///< 0: from the CDM's OBJECT_DESIGNATORs
  int event_version = 0;  ///< 0: from the CDM's CREATION_DATE (seconds since 2000-01-01)
};
ParamTable<ConjunctionUplinkConfig> conjunction_uplink_params() noexcept;

struct ConjunctionUplink {
  autonomy::ConjunctionEvent event;
  std::string source;          ///< "cdm FILE"
  std::string message_id;      ///< the CDM's MESSAGE_ID
  std::string object1, object2;  ///< OBJECT_DESIGNATORs
  std::string tca_utc;         ///< the CDM's TCA
  std::string creation_date;   ///< the CDM's CREATION_DATE
  ConjunctionUplinkConfig config;
};

/// The event of a CDM's text (KVN or XML; ccsds::CdmError for a malformed one), named cdm_name,
/// with the uplink.* settings of sc (typed flags: Scenario::set_value) and hbr_m (<= 0: from
/// AREA_PC), checked at now_us [Unix us]. Throws config::ConfigError for a bad setting and
/// std::invalid_argument naming the flag or keyword for an event the node would refuse.
ConjunctionUplink read_conjunction_uplink(const config::Scenario& sc, const std::string& cdm_text,
                                          const std::string& cdm_name, double hbr_m,
                                          std::int64_t now_us);

/// The event id of a pair of object designators: FNV-1a (32 bits) of "OBJ1/OBJ2", in
/// [1, 2^31 - 1].
std::int64_t conjunction_event_id(const std::string& object1, const std::string& object2) noexcept;

/// What `evade conjunction` prints: the event as it is sent (ids, TCA, thresholds, window and
/// deadline as UTC and utime, the states [m, m/s] and 6x6 covariances, ECI).
nlohmann::json to_json(const ConjunctionUplink& u);

}  // namespace evade::commands
