// Scenario → SimConfig: states and models here, every tunable through its parameter table
// (sim_params.hpp, guidance_params.hpp, the Earth table). Defaults: the ideal sensor/actuator.
#include "evade/commands/sim_scenario.hpp"

#include <cmath>

#include "evade/config/read_params.hpp"
#include "evade/core/epoch.hpp"
#include "evade/guidance/guidance_params.hpp"
#include "evade/sim/sim_params.hpp"

namespace evade::commands {

sim::SimConfig sim_config_from_scenario(const config::Scenario& sc) {
  sim::SimConfig c;
  constexpr double kR = 1e8;  // |r| bound [m]
  constexpr double kV = 1e5;  // |v| bound [m/s]
  if (sc.has("epoch_utc")) {
    const std::string e = sc.get_string("epoch_utc");
    try {
      (void)parse_calendar_utc(e);
    } catch (const std::exception& ex) {
      throw config::ConfigError("epoch_utc = '" + e + "': " + ex.what());
    }
  }
  if (sc.has("description")) sc.mark_used("description");
  c.satellite0.r_eci_m = sc.get_vec3("satellite.r_eci_m", -kR, kR);
  c.satellite0.v_eci_mps = sc.get_vec3("satellite.v_eci_mps", -kV, kV);
  c.debris0.r_eci_m = sc.get_vec3("debris.r_eci_m", -kR, kR);
  c.debris0.v_eci_mps = sc.get_vec3("debris.v_eci_mps", -kV, kV);
  const std::string g = sc.get_enum("gravity", {"two_body", "two_body_j2"}, "two_body_j2");
  c.gravity = (g == "two_body") ? GravityModel::kTwoBody : GravityModel::kTwoBodyJ2;
  c.earth = config::read_earth(sc);
  config::read_params(sc, "", sim::sim_params(), &c);
  config::read_params(sc, "guidance.", guidance::guidance_params(), &c.guidance);
  return c;
}

}  // namespace evade::commands
