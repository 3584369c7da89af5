// truth_sample (truth_sample.hpp): range, range rate, the true LOS rate and e_θ of one row.
#include "evade/sim/truth_sample.hpp"

#include "evade/guidance/los_geometry.hpp"

namespace evade::sim {

SimSample truth_sample(double t_s, const StateEci& satellite, const StateEci& debris) {
  SimSample s;
  s.t_s = t_s;
  s.satellite = satellite;
  s.debris = debris;
  const Vec3 rr = s.debris.r_eci_m - s.satellite.r_eci_m;
  const Vec3 rv = s.debris.v_eci_mps - s.satellite.v_eci_mps;
  s.range_m = rr.norm();
  s.range_rate_mps = rr.dot(rv) / s.range_m;
  Vec3 u;
  Vec3 ud;
  guidance::los_from_relative(rr, rv, &u, &ud);
  guidance::LosFrame fr;
  if (guidance::los_frame(u, ud, s.satellite.r_eci_m, s.satellite.v_eci_mps, 0.0, &fr)) {
    s.los_rate_true_radps = fr.los_rate_radps;
    s.e_theta_true_eci = fr.e_theta_eci;
  }
  return s;
}

}  // namespace evade::sim
