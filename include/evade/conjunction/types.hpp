// Objects screened for conjunctions and the conjunctions found (paper 002, eq. 1-2).
//
// Reference: Wang Xiaoyu, "Space entity collision prediction algorithm and self-adaptive
// simulation step design", J. Air Force Eng. Univ. 7(6), 2006 (paper 002). Each object has
// a size L (largest distance from its centre of mass to its outline) and a maximum
// position error dR; a pair collides when the distance of the centres is <= R_c (eq. 1-2)
// and is in warning when it is <= N R_c (the warning radius R_CA).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "evade/core/constants.hpp"
#include "evade/core/state.hpp"

namespace evade::conjunction {

/// One space object, its state given at the screening epoch (t = 0).
struct SpaceObject {
  std::string name;
  StateEci state;             ///< ECI (J2000 axes) position and velocity at t = 0 [m, m/s]
  double size_m = 0.0;        ///< L: largest distance centre of mass -> outline [m]
  double pos_error_m = 0.0;   ///< dR: largest position error [m]
};

/// A closest approach (or, in paper mode, a flagged sample) of objects i < j.
struct Conjunction {
  std::size_t i = 0;
  std::size_t j = 0;
  double tca_s = 0.0;          ///< time of closest approach since the epoch [s]
  double miss_m = 0.0;         ///< centre distance at tca_s [m]
  double rel_speed_mps = 0.0;  ///< |v_j - v_i| at tca_s [m/s]
  bool collision = false;      ///< miss_m <= R_c (eq. 2)
  bool warning = false;        ///< miss_m <= N R_c
};

/// Eq. 1: R_c(i, j) = (L_i + dR_i) + (L_j + dR_j) [m].
inline double collision_radius_m(const SpaceObject& a, const SpaceObject& b) {
  return (a.size_m + a.pos_error_m) + (b.size_m + b.pos_error_m);
}

/// Warning radius R_CA = N R_c (section 1, N > 1) [m].
inline double warning_radius_m(const SpaceObject& a, const SpaceObject& b, double n_multiple) {
  return n_multiple * collision_radius_m(a, b);
}

/// Orbit geometry of one object used by the filters (two-body osculating values at t = 0).
struct OrbitShape {
  double a_m = 0.0;
  double e = 0.0;
  double perigee_radius_m = 0.0;
  double apogee_radius_m = 0.0;
};

/// Osculating a, e, perigee and apogee radius of a state. Throws std::invalid_argument for
/// a non-finite state or an unbound orbit (e >= 1).
OrbitShape orbit_shape(const StateEci& s, double mu_m3ps2);

/// Checks every object: finite state, size_m >= 0, pos_error_m >= 0 (finite), bound orbit
/// (e < 1) and perigee radius above the Earth's equatorial radius. Throws
/// std::invalid_argument naming the object's index, name, field, value and allowed range.
void validate_objects(const std::vector<SpaceObject>& objects, const EarthModel& earth);

}  // namespace evade::conjunction
