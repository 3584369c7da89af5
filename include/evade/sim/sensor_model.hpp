// Angle sensor model for the simulator (paper 000 sec. 3: elevation/azimuth of the LOS in the
// satellite-centred ECI-parallel frame, eq. 13–14; rates as a rate-stabilised tracker gives).
// Noise: white Gaussian on ε and on the tangent azimuth component β·cos ε (so it stays
// isotropic and finite at the pole), plus a constant bias on ε and β; samples lost with
// probability dropout_prob. Seeded std::mt19937_64: a run is reproducible.
#pragma once

#include <random>

#include "evade/guidance/guidance_law.hpp"
#include "evade/sim/sim_config.hpp"

namespace evade::sim {

class AngleSensor {
 public:
  explicit AngleSensor(const SensorConfig& cfg);
  /// Measurement of the debris seen from the satellite at utime_us. Returns false on a
  /// dropout (the measurement is not produced).
  bool measure(std::int64_t utime_us, const StateEci& satellite, const StateEci& debris,
               guidance::AnglesMeasurement* out);

 private:
  SensorConfig cfg_;
  std::mt19937_64 rng_;
  std::normal_distribution<double> normal_{0.0, 1.0};
  std::uniform_real_distribution<double> uniform_{0.0, 1.0};
  std::int64_t seq_ = 0;
};

}  // namespace evade::sim
