// The encounter plane (B-plane) of a short-term encounter at TCA.
//
// Foster & Estes 1992; Chan 2008 ch. 4; Alfano 2005: with the relative position
// r = r2 - r1 and velocity v = v2 - v1 at TCA (r . v = 0), the encounter frame has
// y_hat = v/|v| (the relative-motion direction, integrated out), x_hat along r (the miss),
// z_hat = x_hat x y_hat; when the miss is zero x_hat is any unit vector normal to v. The
// combined position covariance C = C1 + C2 (the objects' errors are independent) projected on
// (x_hat, z_hat) gives the 2x2 encounter-plane covariance; its eigen-decomposition gives the
// principal axes in which pc_2d works (PrincipalEncounter).
#pragma once

#include <Eigen/Dense>

#include "evade/assessment/pc_2d.hpp"
#include "evade/core/state.hpp"

namespace evade::assessment {

using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;

struct EncounterPlane {
  Vec2 miss_m = Vec2::Zero();      ///< miss in the encounter frame (x along the miss) [m]
  Mat2 cov_m2 = Mat2::Zero();      ///< combined covariance in the same frame [m^2]
  double miss_3d_m = 0.0;          ///< |r2 - r1| [m]
  double rel_speed_mps = 0.0;      ///< |v2 - v1| [m/s]
  double tca_offset_check = 0.0;   ///< r.v / (|r||v|): 0 at an exact TCA
  Mat3 axes_eci = Mat3::Identity();  ///< rows: x_hat, y_hat (relative velocity), z_hat
};

/// Throws std::invalid_argument when the relative speed is zero.
EncounterPlane encounter_plane(const StateEci& obj1, const Mat3& cov1_eci_m2,
                               const StateEci& obj2, const Mat3& cov2_eci_m2);

/// The miss and sigmas in the principal axes of the encounter-plane covariance (x: the
/// axis of the smaller sigma).
PrincipalEncounter principal_axes(const EncounterPlane& ep);

}  // namespace evade::assessment
