// Orbit propagation entry points: analytic two-body (Kepler f and g, Vallado 4th ed.
// sec. 2.3) and numerical two-body + J2 (DOP853, Hairer–Nørsett–Wanner I sec. II.10, with
// the J2 acceleration of Vallado eq. 8-30). Sampling uses the 7th-order dense output.
#include "evade/dynamics/orbit_propagator.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "evade/dynamics/kepler_propagator.hpp"

namespace evade {
namespace {

void check_state(const StateEci& s, const char* who) {
  if (!s.r_eci_m.allFinite() || !s.v_eci_mps.allFinite()) {
    throw std::invalid_argument(std::string(who) + ": non-finite initial state");
  }
}

}  // namespace

StateEci propagate_orbit(const StateEci& s0, double dt_s, GravityModel model,
                         const EarthModel& earth, const AdaptiveOptions& opt,
                         IntegrationStats* stats) {
  check_state(s0, "propagate_orbit");
  if (!std::isfinite(dt_s)) throw std::invalid_argument("propagate_orbit: dt_s is not finite");
  if (model == GravityModel::kTwoBody) {
    if (stats != nullptr) *stats = IntegrationStats{};
    return propagate_kepler(s0, dt_s, earth.mu_m3ps2);
  }
  auto rhs = [model, &earth](double, const Vec6& x) { return orbit_derivative(x, model, earth); };
  return StateEci::from_stacked(propagate_adaptive(rhs, 0.0, s0.stacked(), dt_s, opt, stats));
}

std::vector<StateEci> propagate_orbit_samples(const StateEci& s0, const std::vector<double>& dt_s,
                                              GravityModel model, const EarthModel& earth,
                                              const AdaptiveOptions& opt) {
  check_state(s0, "propagate_orbit_samples");
  for (double t : dt_s) {
    if (!std::isfinite(t)) throw std::invalid_argument("propagate_orbit_samples: non-finite dt");
  }
  std::vector<StateEci> out(dt_s.size(), s0);
  if (model == GravityModel::kTwoBody) {
    for (std::size_t k = 0; k < dt_s.size(); ++k) out[k] = propagate_kepler(s0, dt_s[k], earth.mu_m3ps2);
    return out;
  }
  auto rhs = [model, &earth](double, const Vec6& x) { return orbit_derivative(x, model, earth); };
  // Sample indices sorted by |dt| for each direction; walk the dense output through them.
  std::vector<std::size_t> order(dt_s.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return std::abs(dt_s[a]) < std::abs(dt_s[b]);
  });
  for (double sign : {1.0, -1.0}) {
    double t_end = 0.0;
    for (std::size_t k : order) {
      if (dt_s[k] * sign > 0.0) t_end = dt_s[k];
    }
    if (t_end == 0.0) continue;
    Dop853<Vec6> integ(rhs, opt);
    integ.reset(0.0, s0.stacked());
    for (std::size_t k : order) {
      const double t = dt_s[k];
      if (!(t * sign > 0.0)) continue;
      while ((integ.t_s() - t) * sign < 0.0) {
        if (!integ.step(t_end)) {
          throw std::runtime_error("propagate_orbit_samples: " + integ.failure_reason());
        }
      }
      out[k] = StateEci::from_stacked(t == integ.t_s() ? integ.x() : integ.dense(t));
    }
  }
  return out;
}

}  // namespace evade
