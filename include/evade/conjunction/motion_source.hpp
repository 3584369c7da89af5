// Objects whose motion is given as a function of time rather than by a force model (issue
// 12: a catalog moving by SGP4), for the robust screener and the reference screener.
//
// The screener's no-miss theorem (docs/VALIDATION.md, "Robust mode with SGP4 motion") needs,
// besides the states, a bound on how far the motion's acceleration departs from the
// two-body + J2 field a(r) of the screener's Earth model: for object i and every t of the
// screened span, with p_i(t) = r_i''(t) - a(r_i(t)),
//   |p_i(t)| <= accel_mps2   and   |p_i'(t)| <= rate_mps3.
// The velocity a source returns must be the time derivative of the position it returns
// (the screener's range rate is rho . rho'), not some other velocity, to within
// velocity_error_mps().
#pragma once

#include <cstddef>
#include <string>

#include "evade/core/constants.hpp"
#include "evade/core/state.hpp"

namespace evade::conjunction {

/// Bounds on the perturbation p(t) = r''(t) - a(r(t)) of one object over the span.
struct PerturbationBound {
  double accel_mps2 = 0.0;  ///< |p(t)| <= accel_mps2
  double rate_mps3 = 0.0;   ///< |p'(t)| <= rate_mps3
};

class MotionSource {
 public:
  virtual ~MotionSource() = default;
  /// Number of objects (the screener's objects, in the same order).
  virtual std::size_t size() const = 0;
  /// Position and velocity (= d position / dt) of object i at t_s seconds from the
  /// screening start. Thread-safe. Throws std::runtime_error naming the object when the
  /// motion is undefined there (e.g. an SGP4 error).
  virtual StateEci state_at(std::size_t i, double t_s) const = 0;
  /// The bound on the departure from two-body + J2 of reference_earth() over the span.
  virtual PerturbationBound perturbation(std::size_t i) const = 0;
  /// r''(t_s) of object i in a_mps2 and a bound on that value's error in error_mps2, when
  /// the source can give it more tightly than a(r) +- perturbation(i).accel_mps2; false
  /// when it cannot (the default). Thread-safe.
  virtual bool acceleration_at(std::size_t i, double t_s, Vec3& a_mps2, double& error_mps2) const {
    (void)i, (void)t_s, (void)a_mps2, (void)error_mps2;
    return false;
  }
  /// A bound on |v - r'| for the velocity state_at returns (0: exact). The screener widens
  /// its range-rate tests by it.
  virtual double velocity_error_mps(std::size_t i) const {
    (void)i;
    return 0.0;
  }
  /// A cheaper state for the broad phase's grid (SGP4: its own velocity, one evaluation
  /// instead of the three of state_at's central difference), whose velocity may differ from
  /// r' by up to grid_velocity_error_mps(i); the position is state_at's. Default: state_at.
  /// Thread-safe; throws as state_at.
  virtual StateEci grid_state_at(std::size_t i, double t_s) const { return state_at(i, t_s); }
  /// The grid states of objects [begin, end) at t_s into out[begin], ..., out[end - 1]
  /// (default: grid_state_at one by one). A source may compute several objects at once; its
  /// positions may then differ from state_at's by up to grid_position_error_m(i). Calls on
  /// disjoint ranges may run concurrently; throws as state_at.
  virtual void grid_states_at(double t_s, std::size_t begin, std::size_t end, StateEci* out) const {
    for (std::size_t i = begin; i < end; ++i) out[i] = grid_state_at(i, t_s);
  }
  /// A bound on |v - r'| for grid_state_at (default: velocity_error_mps(i)).
  virtual double grid_velocity_error_mps(std::size_t i) const { return velocity_error_mps(i); }
  /// A bound on |r - state_at(i, t).r| for the positions grid_states_at gives (default 0:
  /// the same positions). The broad phase widens its boxes and tests by it.
  virtual double grid_position_error_m(std::size_t i) const {
    (void)i;
    return 0.0;
  }
  /// True when grid_state_at is not state_at: the screener then takes the states the narrow
  /// phase starts from from state_at, and the grid's only for the boxes and arc bounds.
  virtual bool has_grid_states() const { return false; }
  /// The Earth model the perturbation is measured against; the screener must use it.
  virtual EarthModel reference_earth() const = 0;
  /// The frame of the states ("TEME", "J2000"), for reports.
  virtual std::string frame() const = 0;
};

}  // namespace evade::conjunction
