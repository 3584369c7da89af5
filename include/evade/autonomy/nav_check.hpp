// The uplinked own state against the node's own navigation (docs/AUTONOMY.md AUT-2): the
// node's nav at now, propagated to TCA (two-body + J2, orbit_stm), against the event's object 1
// at TCA, as a Mahalanobis distance in the event's position covariance of object 1. An event
// whose own state is further than the bound (node.autonomy.nav_mismatch_sigma) describes
// another orbit than the one the node flies: it is refused (nav_mismatch), never acted on.
// The 3x3 covariance's eigenvalues are floored at (1 m)^2, so a near-singular covariance cannot
// make a metre look like thousands of sigma. Flight code: no allocation, no exceptions.
#pragma once

#include <cstdint>

#include "evade/autonomy/conjunction_event.hpp"
#include "evade/core/constants.hpp"

namespace evade::autonomy {

struct NavCheck {
  bool ok = false;            ///< the propagation succeeded (else the distances are 0)
  double sigma = 0.0;         ///< Mahalanobis distance of the position difference [-]
  double distance_m = 0.0;    ///< |r_nav(TCA) - r1| [m]
  Vec6 x_nav_tca = Vec6::Zero();  ///< the node's nav propagated to TCA
};

/// x_nav_eci: the node's nav at now_us. h_max_s: the propagation step (docs/AUTONOMY.md).
NavCheck check_own_state(const ConjunctionEvent& e, const Vec6& x_nav_eci, std::int64_t now_us,
                         double h_max_s, const EarthModel& earth) noexcept;

/// sqrt(d^T C^-1 d) with C's eigenvalues floored at floor_m2 [-].
double mahalanobis(const Vec3& d, const Mat3& c, double floor_m2) noexcept;

}  // namespace evade::autonomy
