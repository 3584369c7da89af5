// In-process guidance endpoint: the GuidanceLaw (paper 000) called directly, once per cycle.
#include <memory>

#include "evade/sim/guidance_endpoint.hpp"

namespace evade::sim {

namespace {

class InProcessEndpoint final : public GuidanceEndpoint {
 public:
  InProcessEndpoint(const guidance::GuidanceConfig& cfg, bool armed) : law_(cfg), armed_(armed) {}

  guidance::ThrustCommand exchange(std::int64_t utime_us, const guidance::NavState& nav,
                                   const guidance::AnglesMeasurement* meas) override {
    guidance::GuidanceInput in;
    in.nav = nav;
    in.armed = armed_;
    in.has_measurement = (meas != nullptr);
    if (meas != nullptr) in.meas = *meas;
    return law_.step(in, utime_us);
  }

  bool status(guidance::GuidanceStatus* out) const override {
    *out = law_.status();
    return true;
  }

 private:
  guidance::GuidanceLaw law_;
  bool armed_;
};

}  // namespace

std::unique_ptr<GuidanceEndpoint> make_in_process_endpoint(const guidance::GuidanceConfig& cfg) {
  return std::make_unique<InProcessEndpoint>(cfg, true);
}

std::unique_ptr<GuidanceEndpoint> make_in_process_endpoint(const guidance::GuidanceConfig& cfg,
                                                           bool armed) {
  return std::make_unique<InProcessEndpoint>(cfg, armed);
}

}  // namespace evade::sim
