// Run-time overrides of a simulation scenario (sim_overrides.hpp; paper 000 sec. 4–5).
#include "evade/commands/sim_overrides.hpp"

#include <string>

#include "evade/commands/sim_scenario.hpp"

namespace evade::commands {
namespace {

bool given(const SimOverrides& o, const std::string& key) {
  for (const ParamValue& v : o.params) {
    if (v.key == key) return true;
  }
  return false;
}

}  // namespace

void apply_sim_overrides(const SimOverrides& o, config::Scenario* sc) {
  for (const ParamValue& v : o.params) sc->set_value(v);
  if (o.no_rates || (given(o, "sensor.noise_rad") && !given(o, "sensor.rate_noise_radps"))) {
    sc->set_value(ParamValue{"sensor.has_rates", 0.0});
  }
}

sim::SimConfig read_sim_config(const config::Scenario& sc) {
  sim::SimConfig cfg = sim_config_from_scenario(sc);
  sc.check_all_used();
  cfg.validate();
  return cfg;
}

}  // namespace evade::commands
