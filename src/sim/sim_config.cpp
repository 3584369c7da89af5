// SimConfig::validate (include/evade/sim/sim_config.hpp): the states, then every parameter
// through its table (sim_params, guidance_params), then the integrator's own checks.
#include "evade/sim/sim_config.hpp"

#include <stdexcept>
#include <string>

#include "evade/sim/sim_params.hpp"

namespace evade::sim {
namespace {

bool finite_state(const StateEci& s) { return s.r_eci_m.allFinite() && s.v_eci_mps.allFinite(); }

}  // namespace

void SimConfig::validate() const {
  if (!finite_state(satellite0) || !(satellite0.r_eci_m.norm() > 0.0)) {
    throw std::invalid_argument("sim.satellite: state not finite or zero position");
  }
  if (!finite_state(debris0) || !(debris0.r_eci_m.norm() > 0.0)) {
    throw std::invalid_argument("sim.debris: state not finite or zero position");
  }
  std::string err = validate_params(sim_params(), *this, "");
  if (err.empty()) err = guidance.validate();
  if (!err.empty()) throw std::invalid_argument(err);
  integrator.validate();
}

}  // namespace evade::sim
