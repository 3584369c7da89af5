// Run-time overrides of a simulation scenario (sim_overrides.hpp; paper 000 sec. 4–5).
#include "evade/commands/sim_overrides.hpp"

#include <string>

#include "evade/commands/sim_scenario.hpp"

namespace evade::commands {
namespace {

bool given(const SimOverrides& o, const std::string& key) {
  for (const std::string& kv : o.params) {
    if (kv.compare(0, key.size() + 1, key + "=") == 0) return true;
  }
  return false;
}

}  // namespace

void apply_sim_overrides(const SimOverrides& o, config::Scenario* sc) {
  for (const std::string& kv : o.params) sc->apply_override(kv);
  if (o.no_rates || (given(o, "sensor.noise_rad") && !given(o, "sensor.rate_noise_radps"))) {
    sc->apply_override("sensor.has_rates=false");
  }
}

sim::SimConfig read_sim_config(const config::Scenario& sc) {
  sim::SimConfig cfg = sim_config_from_scenario(sc);
  sc.check_all_used();
  cfg.validate();
  return cfg;
}

}  // namespace evade::commands
