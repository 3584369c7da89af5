// Object states for the screening (see ephemeris.hpp): analytic two-body or DOP853 + J2.
#include "evade/conjunction/ephemeris.hpp"

#include <stdexcept>
#include <string>

#include "evade/dynamics/orbit_propagator.hpp"

namespace evade::conjunction {

Ephemeris::Ephemeris(const std::vector<SpaceObject>& objects, GravityModel gravity,
                     const EarthModel& earth, const AdaptiveOptions& integ)
    : n_(objects.size()), gravity_(gravity), earth_(earth), integ_(integ) {
  integ_.validate();
  if (gravity_ == GravityModel::kTwoBody) {
    kepler_.reserve(n_);
    for (const auto& o : objects) kepler_.emplace_back(o.state, earth_.mu_m3ps2);
  } else {
    const EarthModel e = earth_;
    auto rhs = [e](double, const Vec6& x) { return orbit_derivative(x, GravityModel::kTwoBodyJ2, e); };
    numeric_.reserve(n_);
    for (const auto& o : objects) {
      numeric_.push_back(std::make_unique<Dop853<Vec6>>(rhs, integ_));
      numeric_.back()->reset(0.0, o.state.stacked());
    }
  }
}

Ephemeris::~Ephemeris() = default;

void Ephemeris::states_at(double t_s, std::vector<StateEci>& out) {
  out.resize(n_);
  if (gravity_ == GravityModel::kTwoBody) {
    for (std::size_t i = 0; i < n_; ++i) out[i] = kepler_[i].state_at(t_s);
    return;
  }
  for (std::size_t i = 0; i < n_; ++i) {
    Dop853<Vec6>& integ = *numeric_[i];
    if (t_s < integ.t_s()) {
      throw std::logic_error("Ephemeris::states_at: time went backwards (J2 path)");
    }
    while (integ.t_s() != t_s) {
      if (!integ.step(t_s)) {
        throw std::runtime_error("Ephemeris: object " + std::to_string(i) + ": " +
                                 integ.failure_reason());
      }
    }
    out[i] = StateEci::from_stacked(integ.x());
  }
}

StateEci Ephemeris::state_near(std::size_t i, double t_s, const StateEci& s_grid,
                               double t_grid) const {
  if (gravity_ == GravityModel::kTwoBody) return kepler_[i].state_at(t_s);
  return propagate_orbit(s_grid, t_s - t_grid, GravityModel::kTwoBodyJ2, earth_, integ_);
}

}  // namespace evade::conjunction
