// Thruster model (see include/evade/sim/actuator_model.hpp).
#include "evade/sim/actuator_model.hpp"

#include <algorithm>
#include <cmath>

#include "evade/core/constants.hpp"

namespace evade::sim {

Actuator::Actuator(const ActuatorConfig& cfg) : cfg_(cfg), rng_(cfg.seed) {}

Vec3 Actuator::accel_eci_mps2(const guidance::ThrustCommand& cmd) {
  const double err = cfg_.direction_error_rad * normal_(rng_);
  const double phase = kTwoPi * uniform_(rng_);
  const double n = cmd.u_eci.norm();
  if (!(cmd.accel_mps2 > 0.0) || !std::isfinite(cmd.accel_mps2) || !(n > 0.0) ||
      !cmd.u_eci.allFinite()) {
    return Vec3::Zero();
  }
  const double a = std::min(cmd.accel_mps2, cfg_.max_accel_mps2);
  Vec3 d = cmd.u_eci / n;
  if (err != 0.0) {
    // Random axis perpendicular to d, then rotate d about it by err.
    const Vec3 ref = (std::abs(d.x()) < 0.9) ? Vec3::UnitX() : Vec3::UnitY();
    const Vec3 p1 = d.cross(ref).normalized();
    const Vec3 p2 = d.cross(p1);
    const Vec3 axis = std::cos(phase) * p1 + std::sin(phase) * p2;
    d = std::cos(err) * d + std::sin(err) * axis.cross(d);
  }
  return a * d;
}

}  // namespace evade::sim
