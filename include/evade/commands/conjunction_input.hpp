// Readers of a conjunction for assessment: a scenario's `conjunction:` block (hbr_m;
// object1/object2 with r_eci_m [3], v_eci_mps [3] and cov_eci_m2 or cov_rtn_m2 as a 3x3
// position or 6x6 position-velocity nested list; the RTN frame is the object's own) and a
// CDM (states and RTN covariances of both objects; HBR given by the caller or, when both
// objects carry AREA_PC, sqrt(A1/pi) + sqrt(A2/pi)).
#pragma once

#include "evade/assessment/assess.hpp"
#include "evade/ccsds/cdm.hpp"
#include "evade/config/scenario.hpp"

namespace evade::commands {

/// Throws config::ConfigError naming the key.
assessment::ConjunctionInput read_conjunction_scenario(const config::Scenario& sc);
/// hbr_m <= 0: from AREA_PC of both objects, else std::invalid_argument.
assessment::ConjunctionInput conjunction_from_cdm(const ccsds::Cdm& cdm, double hbr_m,
                                                  const EarthModel& earth);

}  // namespace evade::commands
