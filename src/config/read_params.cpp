// Earth constants from a scenario, through the one Earth table (core/earth_params.hpp).
#include "evade/config/read_params.hpp"

#include "evade/core/earth_params.hpp"

namespace evade::config {

EarthModel read_earth(const Scenario& sc, const EarthModel& defaults) {
  EarthModel e = defaults;
  read_params(sc, "earth.", earth_params(), &e);
  return e;
}

}  // namespace evade::config
