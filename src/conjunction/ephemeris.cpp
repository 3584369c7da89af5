// Object states for the screening (see ephemeris.hpp): analytic two-body or DOP853 + J2.
#include "evade/conjunction/ephemeris.hpp"

#include <stdexcept>
#include <utility>
#include <string>

#include "evade/dynamics/orbit_propagator.hpp"

namespace evade::conjunction {

namespace {

[[noreturn]] void integration_failed(std::size_t i, const OrbitIntegrator& integ) {
  throw std::runtime_error("Ephemeris: object " + std::to_string(i) + ": " + integ.failure_reason());
}

}  // namespace

StepArcs::StepArcs(std::size_t n_objects, const OrbitIntegrator& prototype)
    : prototype_(prototype), arc_of_(n_objects, -1) {}

StateEci StepArcs::at(std::size_t i, double t_s, const StateEci& s_grid, double t_grid) {
  if (t_s == t_grid) return s_grid;
  if (t_s < t_grid) throw std::logic_error("Ephemeris::state_near: time before the grid time");
  if (t_grid != t_grid_) {
    for (std::size_t k : objects_) arc_of_[k] = -1;
    objects_.clear();
    t_grid_ = t_grid;
  }
  if (arc_of_[i] < 0) {
    arc_of_[i] = static_cast<long>(objects_.size());
    if (objects_.size() == arcs_.size()) arcs_.emplace_back();
    objects_.push_back(i);
    std::vector<OrbitIntegrator>& fresh = arcs_[static_cast<std::size_t>(arc_of_[i])];
    fresh.clear();
    fresh.push_back(prototype_);  // same right-hand side and tolerances
    fresh.back().reset(t_grid, s_grid.stacked());
  }
  std::vector<OrbitIntegrator>& arc = arcs_[static_cast<std::size_t>(arc_of_[i])];
  // Natural steps toward a far end (never clipped), so the arc does not depend on t_s.
  const double t_far = t_grid + 1e7;
  while (arc.back().t_s() < t_s) {
    arc.push_back(arc.back());
    if (!arc.back().step(t_far)) integration_failed(i, arc.back());
  }
  // The first step whose end reaches t_s holds it (arc[0] is the reset state).
  std::size_t k = 1;
  while (arc[k].t_s() < t_s) ++k;
  const OrbitIntegrator& in = arc[k];
  return StateEci::from_stacked(t_s == in.t_s() ? in.x() : in.dense(t_s));
}

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
    const OrbitIntegrator proto(OrbitRhs{GravityModel::kTwoBodyJ2, earth_}, integ_);
    numeric_.assign(n_, proto);
    for (std::size_t i = 0; i < n_; ++i) numeric_[i].reset(0.0, objects[i].state.stacked());
    arcs_ = std::make_unique<StepArcs>(make_arcs());
  }
}

Ephemeris::~Ephemeris() = default;

void Ephemeris::states_at(double t_s, std::vector<StateEci>& out) {
  out.resize(n_);
  states_at(t_s, 0, n_, out.data());
}

void Ephemeris::states_at(double t_s, std::size_t begin, std::size_t end, StateEci* out) {
  if (motion_) {
    for (std::size_t i = begin; i < end; ++i) out[i] = motion_->state_at(i, t_s);
    return;
  }
  if (gravity_ == GravityModel::kTwoBody) {
    for (std::size_t i = begin; i < end; ++i) out[i] = kepler_[i].state_at(t_s);
    return;
  }
  for (std::size_t i = begin; i < end; ++i) {
    OrbitIntegrator& integ = numeric_[i];
    if (t_s < integ.t_s()) {
      throw std::logic_error("Ephemeris::states_at: time went backwards (J2 path)");
    }
    while (integ.t_s() != t_s) {
      if (!integ.step(t_s)) integration_failed(i, integ);
    }
    out[i] = StateEci::from_stacked(integ.x());
  }
}

void Ephemeris::grid_states_at(double t_s, std::size_t begin, std::size_t end, StateEci* out) {
  if (!has_grid_states()) {
    states_at(t_s, begin, end, out);
    return;
  }
  motion_->grid_states_at(t_s, begin, end, out);
}

StepArcs Ephemeris::make_arcs() const {
  return StepArcs(n_, OrbitIntegrator(OrbitRhs{GravityModel::kTwoBodyJ2, earth_}, integ_));
}

StateEci Ephemeris::state_near(std::size_t i, double t_s, const StateEci& s_grid,
                               double t_grid) const {
  if (motion_) return t_s == t_grid ? s_grid : motion_->state_at(i, t_s);
  if (gravity_ == GravityModel::kTwoBody) return kepler_[i].state_at(t_s);
  return arcs_->at(i, t_s, s_grid, t_grid);
}

StateEci Ephemeris::state_near(StepArcs& arcs, std::size_t i, double t_s, const StateEci& s_grid,
                               double t_grid) const {
  if (motion_) return t_s == t_grid ? s_grid : motion_->state_at(i, t_s);
  if (gravity_ == GravityModel::kTwoBody) return kepler_[i].state_at(t_s);
  return arcs.at(i, t_s, s_grid, t_grid);
}

}  // namespace evade::conjunction
