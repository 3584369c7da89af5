// One screening event as a CCSDS Conjunction Data Message (CCSDS 508.0-B-1, Blue Book, June
// 2013, tables 3-2 to 3-6): what `evade screen --cdm-out DIR` writes for every event.
//
// Input: the two objects (designator, catalog, name, international designator), their states
// at TCA in EME2000 (J2000 axes: the population path's ECI as it is, the catalog path's TEME
// rotated by sgp4::teme_to_j2000), the TCA (UTC), the screener's miss distance and relative
// speed, the screening period and threshold, and each object's 6x6 position-velocity
// covariance in its own RTN frame when it is known.
// Output: a message with every mandatory keyword of 508.0-B-1, REF_FRAME = EME2000; the
// relative position and velocity of object 2 with respect to object 1 in object 1's RTN axes
// (the vector difference rotated, no transport term, so |RELATIVE_VELOCITY| = RELATIVE_SPEED);
// SCREEN_VOLUME a sphere of the threshold (RTN, ELLIPSOID with three equal semi-axes).
// Covariance known for both objects: the RTN terms as given, COLLISION_PROBABILITY = the
// recommended Pc (pc_method_choice.hpp: the 2D Pc of Foster & Estes 1992 unless its usage
// checks fail, then 3D-Nc or Monte Carlo), COLLISION_PROBABILITY_METHOD = FOSTER-1992,
// HALL-2021 or ALFANO-2009 with a COMMENT saying why, and the hard-body radius in a
// relative-section COMMENT (and as AREA_PC = pi r^2 per object when the object radii are
// known, so that a reader forming HBR = sqrt(A1/pi) + sqrt(A2/pi) recovers it).
// Covariance not known: the standard still requires the 21 position-velocity terms, so they
// are written as 0 with COVARIANCE_METHOD = DEFAULT and a COMMENT in that covariance section
// saying the covariance is not known; no COLLISION_PROBABILITY is written
// (docs/ASSESSMENT.md, "CDMs from screening"; `evade assess --cdm` refuses an all-zero
// position covariance).
#pragma once

#include <array>
#include <optional>
#include <string>

#include "evade/assessment/assess_params.hpp"
#include "evade/ccsds/cdm.hpp"
#include "evade/core/state.hpp"

namespace evade::commands {

struct EventObject {
  std::string designator;                ///< OBJECT_DESIGNATOR (NORAD id, population name)
  std::string catalog_name = "SATCAT";   ///< CATALOG_NAME
  std::string name;                      ///< OBJECT_NAME
  std::string international_designator;  ///< INTERNATIONAL_DESIGNATOR ("UNKNOWN" when empty)
  StateEci state_eme2000;                ///< at TCA [m, m/s], EME2000 axes
  std::optional<Mat6> cov_rtn;           ///< RTN [m^2, m^2/s, m^2/s^2]; empty: not known
  std::string cov_comment;               ///< where the covariance comes from (a COMMENT)
  double radius_m = 0.0;                 ///< > 0: AREA_PC = pi r^2 written
  std::string state_comment;             ///< how the state was obtained (a metadata COMMENT)
};

struct ScreeningEvent {
  std::array<EventObject, 2> obj;
  double tca_utc_j2000_s = 0.0;  ///< TCA, UTC seconds since J2000
  double miss_m = 0.0;           ///< the screener's miss distance at TCA [m]
  double rel_speed_mps = 0.0;    ///< the screener's |v2 - v1| at TCA [m/s]
  double screen_start_utc_j2000_s = 0.0;
  double screen_stop_utc_j2000_s = 0.0;
  double screen_threshold_m = 0.0;  ///< > 0: SCREEN_VOLUME_* written
};

struct EventCdmOptions {
  std::string originator = "EVADE";
  std::string message_id;                ///< MESSAGE_ID (e.g. cdm_event_file_stem)
  double creation_utc_j2000_s = 0.0;     ///< CREATION_DATE
  double hbr_m = 0.0;                    ///< hard-body radius for the Pc (> 0 with covariances)
  std::string hbr_source;                ///< said in the COMMENT ("sum of the object radii")
  assessment::AssessConfig assess;                   ///< the Pc method choice (pc_method_choice.hpp)
  std::string header_comment;            ///< optional header COMMENT (e.g. the objects' source)
};

struct EventCdm {
  ccsds::Cdm cdm;
  std::optional<double> pc;  ///< the COLLISION_PROBABILITY written, when covariances are known
  std::string pc_method;     ///< the method that gave it: "2d", "3d_nc" or "mc"
};

/// Builds and validates (validate_cdm) the message. Throws std::invalid_argument for a
/// non-finite state, miss or TCA, a miss or speed <= 0 where a Pc is needed, covariances
/// known without hbr_m > 0, or a covariance that is not finite and symmetric.
EventCdm cdm_from_event(const ScreeningEvent& ev, const EventCdmOptions& opt);

/// An epoch as the CDM writes it: "YYYY-MM-DDThh:mm:ss.ffffff" (UTC, rounded to 1 us).
std::string cdm_epoch(double utc_j2000_s);

/// A deterministic file stem for an event: "<designator1>_<designator2>_<YYYYMMDDThhmmss.ffffff>"
/// (characters other than letters, digits, '-' and '.' replaced by '_').
std::string cdm_event_file_stem(const ScreeningEvent& ev);

}  // namespace evade::commands
