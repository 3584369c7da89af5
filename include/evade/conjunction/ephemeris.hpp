// Positions and velocities of every screened object at the screening times.
//
// Two-body: analytic (KeplerOrbit, f and g functions; exact to rounding at any time).
// Two-body + J2: numerical, one DOP853 integrator per object (HNW I sec. II.10, J2 of
// Vallado eq. 8-30) stepped forward to each grid time; a state between two grid times is
// obtained by integrating the short arc from the grid state (propagate_orbit), so every
// state comes from the same force model and tolerance. Grid times must not decrease.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "evade/dynamics/kepler_propagator.hpp"
#include "evade/conjunction/types.hpp"
#include "evade/dynamics/dop853.hpp"
#include "evade/dynamics/gravity.hpp"

namespace evade::conjunction {

class Ephemeris {
 public:
  /// Objects must have passed validate_objects().
  Ephemeris(const std::vector<SpaceObject>& objects, GravityModel gravity, const EarthModel& earth,
            const AdaptiveOptions& integ = AdaptiveOptions::tight());
  ~Ephemeris();
  Ephemeris(const Ephemeris&) = delete;
  Ephemeris& operator=(const Ephemeris&) = delete;

  std::size_t size() const { return n_; }
  /// States of all objects at t_s (seconds since the epoch). For J2, t_s must not be
  /// earlier than the previous call's.
  void states_at(double t_s, std::vector<StateEci>& out);
  /// State of object i at t_s, given its state s_grid at a grid time t_grid (from
  /// states_at); t_s should lie within a screening step of t_grid.
  StateEci state_near(std::size_t i, double t_s, const StateEci& s_grid, double t_grid) const;

 private:
  std::size_t n_ = 0;
  GravityModel gravity_;
  EarthModel earth_;
  AdaptiveOptions integ_;
  std::vector<KeplerOrbit> kepler_;
  std::vector<std::unique_ptr<Dop853<Vec6>>> numeric_;
};

}  // namespace evade::conjunction
