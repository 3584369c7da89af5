// The events of a screening as commands::ScreeningEvent, the input of one CCSDS CDM each
// (assessment/screen_cdms.hpp; CCSDS 508.0-B-1): both objects named and their states at the
// TCA in EME2000.
//   Objects (scenario, CSV, synthetic population): the states of event_states (two-body
//   Kepler or two-body + J2 DOP853 from t = 0), whose ECI axes are J2000 = EME2000;
//   designator = name, catalog EVADE, radius = SpaceObject::size_m.
//   SGP4 catalog: event_states gives TEME (Sgp4Motion); it is rotated to EME2000 at the TCA
//   by sgp4::teme_to_j2000 (IAU-76/80; Vallado, Crawford, Hujsak & Kelso 2006, AIAA
//   2006-6753); designator = NORAD id, name and international designator (CCSDS form
//   "YYYY-NNNP") from the element set, no radius (catalogs carry no sizes).
// TCAs are UTC seconds since J2000: the screening's epoch plus the event's tca_s.
#pragma once

#include <string>
#include <vector>

#include "evade/commands/cdm_from_event.hpp"
#include "evade/conjunction/robust_screen.hpp"
#include "evade/conjunction/sgp4_motion.hpp"
#include "evade/conjunction/types.hpp"
#include "evade/sgp4/mean_elements.hpp"

namespace evade::commands {

/// Events of objects with states at t = 0 (so: the options of the screening, its force model).
std::vector<commands::ScreeningEvent> object_screening_events(
    const std::vector<conjunction::Conjunction>& events, const std::vector<conjunction::SpaceObject>& objects,
    const conjunction::ScreenOptions& so, double epoch_utc_j2000_s);

/// Events of an SGP4 catalog screening (s: the screening, elements: the catalog's element
/// sets, for names and international designators).
std::vector<commands::ScreeningEvent> catalog_screening_events(
    const std::vector<conjunction::Conjunction>& events, const conjunction::Sgp4Screening& s,
    const std::vector<sgp4::MeanElements>& elements, const conjunction::ScreenOptions& so);

/// "58002B" (TLE columns 10-17) -> "1958-002B" (CCSDS 508.0-B-1 YYYY-NNNP{PP}); other text
/// as it is.
std::string ccsds_international_designator(const std::string& id);

}  // namespace evade::commands
