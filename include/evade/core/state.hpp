// Fixed-size state types shared by every module. Frames are in the type or field names.
#pragma once

#include <Eigen/Dense>

namespace evade {

using Vec3 = Eigen::Vector3d;
using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat3 = Eigen::Matrix3d;
using Mat6 = Eigen::Matrix<double, 6, 6>;

/// Position and velocity in the Earth-centred inertial frame (J2000 axes).
struct StateEci {
  Vec3 r_eci_m = Vec3::Zero();    ///< position [m]
  Vec3 v_eci_mps = Vec3::Zero();  ///< velocity [m/s]

  /// Packs [r; v] into one 6-vector (the integrators' state layout).
  Vec6 stacked() const {
    Vec6 x;
    x << r_eci_m, v_eci_mps;
    return x;
  }
  static StateEci from_stacked(const Vec6& x) { return {x.head<3>(), x.tail<3>()}; }
};

}  // namespace evade
