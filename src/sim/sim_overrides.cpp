// Run-time overrides of a simulation scenario (sim_overrides.hpp; paper 000 sec. 4–5).
#include "evade/sim/sim_overrides.hpp"

#include <iomanip>
#include <sstream>
#include <string>

#include "evade/sim/sim_scenario.hpp"

namespace evade::sim {
namespace {

// key=value with the value written so that it reads back as the same double.
void override_key(config::Scenario* sc, const char* key, const std::optional<double>& v) {
  if (!v) return;
  std::ostringstream os;
  os << std::setprecision(17) << *v;
  sc->apply_override(std::string(key) + "=" + os.str());
}

}  // namespace

void apply_sim_overrides(const SimOverrides& o, config::Scenario* sc) {
  override_key(sc, "guidance.max_accel_mps2", o.max_accel_mps2);
  override_key(sc, "encounter.detect_before_tca_s", o.detect_before_tca_s);
  override_key(sc, "sensor.noise_rad", o.noise_rad);
  override_key(sc, "sensor.rate_hz", o.sensor_rate_hz);
  override_key(sc, "guidance.rate_hz", o.guidance_rate_hz);
  override_key(sc, "sensor.rate_noise_radps", o.rate_noise_radps);
  if (o.no_rates || (o.noise_rad && !o.rate_noise_radps)) {
    sc->apply_override("sensor.has_rates=false");
  }
}

SimConfig read_sim_config(const config::Scenario& sc) {
  SimConfig cfg = sim_config_from_scenario(sc);
  sc.check_all_used();
  cfg.validate();
  return cfg;
}

}  // namespace evade::sim
