// The simulator's view of the guidance: one exchange per guidance cycle.
//
// The simulator (sim module, pure) owns the truth, the sensor and the actuator; the guidance
// sits behind this interface so it can run in-process (make_in_process_endpoint) or in
// another process over LCM (the LCM implementation is evade::lcm_link::make_lcm_endpoint).
// Nothing here knows about LCM.
#pragma once

#include <cstdint>
#include <memory>

#include "evade/guidance/guidance_law.hpp"

namespace evade::sim {

class GuidanceEndpoint {  // one exchange per guidance cycle
 public:
  virtual ~GuidanceEndpoint() = default;
  /// Sends this cycle's clock tick, nav state and (possibly no: nullptr) measurement; returns
  /// the command in force. `armed` is fixed per run by the scenario (guidance.armed).
  virtual guidance::ThrustCommand exchange(std::int64_t utime_us, const guidance::NavState& nav,
                                           const guidance::AnglesMeasurement* meas) = 0;
  /// Latest guidance status if the endpoint can see it (in-process: always; LCM: the last
  /// status message received). Returns false if none is available.
  virtual bool status(guidance::GuidanceStatus* out) const {
    (void)out;
    return false;
  }
};

/// The guidance law run in this process, armed. Throws std::invalid_argument on a bad config.
std::unique_ptr<GuidanceEndpoint> make_in_process_endpoint(const guidance::GuidanceConfig& cfg);
/// Same, with an explicit arm flag (a disarmed run is the no-thrust baseline).
std::unique_ptr<GuidanceEndpoint> make_in_process_endpoint(const guidance::GuidanceConfig& cfg,
                                                           bool armed);

}  // namespace evade::sim
