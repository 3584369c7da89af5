// Encounter-plane projection (include/evade/assessment/encounter_plane.hpp gives the source).
#include "evade/assessment/encounter_plane.hpp"

#include <stdexcept>

#include "evade/assessment/encounter_2d.hpp"

namespace evade::assessment {

// The flight form (encounter_2d.hpp) with its refusals thrown.
EncounterPlane encounter_plane(const StateEci& obj1, const Mat3& cov1_eci_m2,
                               const StateEci& obj2, const Mat3& cov2_eci_m2) {
  EncounterPlane ep;
  if (!encounter_plane_into(obj1, cov1_eci_m2, obj2, cov2_eci_m2, &ep)) {
    throw std::invalid_argument("encounter plane: relative speed is zero (no encounter plane)");
  }
  return ep;
}

PrincipalEncounter principal_axes(const EncounterPlane& ep) {
  PrincipalEncounter pe;
  if (!principal_axes_into(ep, &pe)) {
    throw std::invalid_argument("encounter plane: combined covariance is not positive definite");
  }
  return pe;
}

}  // namespace evade::assessment
