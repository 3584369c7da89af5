// Positions and velocities of every screened object at the screening times.
//
// Two-body: analytic (KeplerOrbit, f and g functions; exact to rounding at any time).
// Two-body + J2: numerical, one DOP853 integrator per object (HNW I sec. II.10, J2 of
// Vallado eq. 8-30, right-hand side inlined: orbit_rhs.hpp) stepped forward to each grid
// time; a state between two grid times comes from the arc integrated from the grid state on
// the integrator's own steps and read from its 7th-order dense output (HNW I sec. II.6). The
// arc of an object is integrated once per grid step and shared by all its pairs (StepArcs,
// one per thread); it does not depend on which times were asked first, so results do not
// depend on the order of the pairs. Grid times must not decrease.
// A MotionSource (motion_source.hpp; e.g. SGP4), when given, replaces both: every state
// comes from it.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "evade/dynamics/kepler_propagator.hpp"
#include "evade/conjunction/motion_source.hpp"
#include "evade/conjunction/types.hpp"
#include "evade/dynamics/dop853.hpp"
#include "evade/dynamics/gravity.hpp"
#include "evade/dynamics/orbit_rhs.hpp"

namespace evade::conjunction {

/// The DOP853 integrator of one object under two-body + J2 (right-hand side inlined).
using OrbitIntegrator = Dop853<Vec6, OrbitRhs>;

/// The J2 arcs of one grid time: for each object asked for, the DOP853 integration from its
/// grid state on the integrator's own steps (never clipped), read through the dense output.
/// An arc does not depend on which times were asked first. One per thread.
class StepArcs {
 public:
  /// prototype: the right-hand side and tolerances every arc is integrated with.
  StepArcs(std::size_t n_objects, const OrbitIntegrator& prototype);
  /// State of object i at t_s >= t_grid from its grid state s_grid at t_grid.
  StateEci at(std::size_t i, double t_s, const StateEci& s_grid, double t_grid);

 private:
  OrbitIntegrator prototype_;
  double t_grid_ = -1.0;
  std::vector<long> arc_of_;                    // arcs_[arc_of_[i]] for object i, or -1
  std::vector<std::size_t> objects_;            // objects with an arc at t_grid_
  std::vector<std::vector<OrbitIntegrator>> arcs_;  // reused: only the first objects_.size()
};

class Ephemeris {
 public:
  /// Objects must have passed validate_objects().
  Ephemeris(const std::vector<SpaceObject>& objects, GravityModel gravity, const EarthModel& earth,
            const AdaptiveOptions& integ = AdaptiveOptions::tight(),
            std::shared_ptr<const MotionSource> motion = nullptr);
  ~Ephemeris();
  Ephemeris(const Ephemeris&) = delete;
  Ephemeris& operator=(const Ephemeris&) = delete;

  std::size_t size() const { return n_; }
  /// States of all objects at t_s (seconds since the epoch). For J2, t_s must not be
  /// earlier than the previous call's.
  void states_at(double t_s, std::vector<StateEci>& out);
  /// Objects [begin, end) only, written to out[begin], ..., out[end - 1]. Calls on disjoint
  /// ranges may run concurrently.
  void states_at(double t_s, std::size_t begin, std::size_t end, StateEci* out);
  /// The broad phase's grid states: states_at, except with a motion source that has cheaper
  /// grid states (MotionSource::grid_states_at), whose velocity is then within
  /// grid_velocity_error_mps(i) of r' and position within grid_position_error_m(i) of the
  /// exact one. Same contract as states_at.
  void grid_states_at(double t_s, std::size_t begin, std::size_t end, StateEci* out);
  /// True when grid_states_at differs from states_at (the narrow phase then starts from
  /// exact_state).
  bool has_grid_states() const { return motion_ && motion_->has_grid_states(); }
  /// Bound on |v - r'| of the velocity grid_states_at gives object i (0: exact).
  double grid_velocity_error_mps(std::size_t i) const {
    return has_grid_states() ? motion_->grid_velocity_error_mps(i) : 0.0;
  }
  /// Bound on |r - exact r| of the position grid_states_at gives object i (0: exact).
  double grid_position_error_m(std::size_t i) const {
    return has_grid_states() ? motion_->grid_position_error_m(i) : 0.0;
  }
  /// State of object i at t_s from the motion source (only with has_grid_states()).
  StateEci exact_state(std::size_t i, double t_s) const { return motion_->state_at(i, t_s); }
  /// State of object i at t_s >= t_grid, given its state s_grid at a grid time t_grid (from
  /// states_at); t_s should lie within a screening step of t_grid. Not thread-safe (the
  /// J2 arcs are cached): one Ephemeris per thread.
  StateEci state_near(std::size_t i, double t_s, const StateEci& s_grid, double t_grid) const;
  /// The same with the caller's arcs (thread-safe with one StepArcs per thread).
  StateEci state_near(StepArcs& arcs, std::size_t i, double t_s, const StateEci& s_grid,
                      double t_grid) const;
  /// Arcs for state_near on another thread.
  StepArcs make_arcs() const;

 private:
  std::size_t n_ = 0;
  GravityModel gravity_;
  EarthModel earth_;
  AdaptiveOptions integ_;
  std::shared_ptr<const MotionSource> motion_;
  std::vector<KeplerOrbit> kepler_;
  std::vector<OrbitIntegrator> numeric_;
  // J2: the arcs of the current grid time for the single-threaded state_near; dropped when
  // a new grid time is asked for, so memory holds only the objects of one grid step.
  mutable std::unique_ptr<StepArcs> arcs_;
};

}  // namespace evade::conjunction
