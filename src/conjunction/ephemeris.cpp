// Object states for the screening (see ephemeris.hpp): analytic two-body or DOP853 + J2.
#include "evade/conjunction/ephemeris.hpp"

#include <stdexcept>
#include <utility>
#include <string>

#include "evade/dynamics/orbit_propagator.hpp"

namespace evade::conjunction {

Ephemeris::Ephemeris(const std::vector<SpaceObject>& objects, GravityModel gravity,
                     const EarthModel& earth, const AdaptiveOptions& integ,
                     std::shared_ptr<const MotionSource> motion)
    : n_(objects.size()), gravity_(gravity), earth_(earth), integ_(integ), motion_(std::move(motion)) {
  integ_.validate();
  if (motion_) {
    if (motion_->size() != n_) throw std::invalid_argument("Ephemeris: motion source size != objects");
  } else if (gravity_ == GravityModel::kTwoBody) {
    kepler_.reserve(n_);
    for (const auto& o : objects) kepler_.emplace_back(o.state, earth_.mu_m3ps2);
  } else {
    arc_of_.assign(n_, -1);
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
  if (motion_) {
    for (std::size_t i = 0; i < n_; ++i) out[i] = motion_->state_at(i, t_s);
    return;
  }
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
  if (motion_) return t_s == t_grid ? s_grid : motion_->state_at(i, t_s);
  if (gravity_ == GravityModel::kTwoBody) return kepler_[i].state_at(t_s);
  if (t_s == t_grid) return s_grid;
  if (t_s < t_grid) throw std::logic_error("Ephemeris::state_near: time before the grid time");
  if (t_grid != arcs_t_grid_) {
    for (std::size_t k : arc_objects_) arc_of_[k] = -1;
    arc_objects_.clear();
    arcs_.clear();
    arcs_t_grid_ = t_grid;
  }
  if (arc_of_[i] < 0) {
    arc_of_[i] = static_cast<long>(arcs_.size());
    arc_objects_.push_back(i);
    arcs_.emplace_back();
    arcs_.back().push_back(*numeric_[i]);  // same right-hand side and tolerances
    arcs_.back().back().reset(t_grid, s_grid.stacked());
  }
  Arc& arc = arcs_[static_cast<std::size_t>(arc_of_[i])];
  // Natural steps toward a far end (never clipped), so the arc does not depend on t_s.
  const double t_far = t_grid + 1e7;
  while (arc.back().t_s() < t_s) {
    Dop853<Vec6> next = arc.back();
    if (!next.step(t_far)) {
      throw std::runtime_error("Ephemeris: object " + std::to_string(i) + ": " + next.failure_reason());
    }
    arc.push_back(std::move(next));
  }
  // The first step whose end reaches t_s holds it (steps[0] is the reset state).
  std::size_t k = 1;
  while (arc[k].t_s() < t_s) ++k;
  const Dop853<Vec6>& in = arc[k];
  return StateEci::from_stacked(t_s == in.t_s() ? in.x() : in.dense(t_s));
}

}  // namespace evade::conjunction
