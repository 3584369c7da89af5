// Positions and velocities of every screened object at the screening times.
//
// Two-body: analytic (KeplerOrbit, f and g functions; exact to rounding at any time).
// Two-body + J2: numerical, one DOP853 integrator per object (HNW I sec. II.10, J2 of
// Vallado eq. 8-30) stepped forward to each grid time; a state between two grid times comes
// from the arc integrated from the grid state on the integrator's own steps and read from its
// 7th-order dense output (HNW I sec. II.6). The arc of an object is integrated once per grid
// step and shared by all its pairs; it does not depend on which times were asked first, so
// results do not depend on the order of the pairs. Grid times must not decrease.
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

namespace evade::conjunction {

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
  /// State of object i at t_s >= t_grid, given its state s_grid at a grid time t_grid (from
  /// states_at); t_s should lie within a screening step of t_grid. Not thread-safe (the
  /// J2 arcs are cached): one Ephemeris per thread.
  StateEci state_near(std::size_t i, double t_s, const StateEci& s_grid, double t_grid) const;

 private:
  std::size_t n_ = 0;
  GravityModel gravity_;
  EarthModel earth_;
  AdaptiveOptions integ_;
  std::shared_ptr<const MotionSource> motion_;
  std::vector<KeplerOrbit> kepler_;
  std::vector<std::unique_ptr<Dop853<Vec6>>> numeric_;
  // J2: the arcs of the current grid time t_grid (the integrator after each of its steps),
  // arcs_[arc_of_[i]] for object i; dropped when a new grid time is asked for, so memory
  // holds only the objects of one grid step.
  using Arc = std::vector<Dop853<Vec6>>;
  mutable double arcs_t_grid_ = -1.0;
  mutable std::vector<Arc> arcs_;
  mutable std::vector<long> arc_of_;
  mutable std::vector<std::size_t> arc_objects_;
};

}  // namespace evade::conjunction
