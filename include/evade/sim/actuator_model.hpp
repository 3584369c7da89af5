// Thruster model for the simulator: the commanded acceleration (paper 000: max acceleration
// along −e_θ) is clipped to the hardware limit and given a random pointing error (angle
// ~ N(0, σ²) about a uniformly random axis perpendicular to the command). Latency and the
// zero-order hold are applied by the simulator (simulator.cpp).
#pragma once

#include <random>

#include "evade/guidance/guidance_law.hpp"
#include "evade/sim/sim_config.hpp"

namespace evade::sim {

class Actuator {
 public:
  explicit Actuator(const ActuatorConfig& cfg);
  /// Acceleration vector [m/s², ECI] that the command produces.
  Vec3 accel_eci_mps2(const guidance::ThrustCommand& cmd);

 private:
  ActuatorConfig cfg_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> normal_{0.0, 1.0};
  std::uniform_real_distribution<double> uniform_{0.0, 1.0};
};

}  // namespace evade::sim
