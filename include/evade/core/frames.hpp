// Local orbital frames built on a reference ("chief") ECI state, and relative-state
// transforms ECI <-> local frame that account for the frame's rotation.
//
// Axis conventions (all right-handed, unit vectors expressed in ECI):
//  * RSW (= LVLH as used in HCW, Vallado sec. 3.3):
//      R (x) radial, along r;  W (z) orbit normal, along h = r x v;  S (y) = W x R, along
//      track (the velocity direction for a circular orbit).
//  * VVLH (CCSDS "LVLH", local-vertical local-horizontal, used by papers 001 and 004):
//      z toward the Earth's centre (-R);  y opposite the orbit normal (-W);  x = y x z,
//      along track (= S).
// A relative state expressed in a rotating frame F is
//      rho_F = C_F_eci (r_dep - r_chief),
//      rhodot_F = C_F_eci ((v_dep - v_chief) - omega_eci x (r_dep - r_chief)),
// with omega_eci = h / |r|^2 the frame's angular velocity (exact for any Keplerian chief).
#pragma once

#include "evade/core/state.hpp"

namespace evade {

/// Rotation matrix whose rows are the R, S, W unit vectors in ECI: v_rsw = C * v_eci.
Mat3 rotation_eci_to_rsw(const StateEci& chief);
/// Rotation matrix whose rows are the VVLH x, y, z unit vectors in ECI.
Mat3 rotation_eci_to_vvlh(const StateEci& chief);
/// Constant rotation RSW -> VVLH: [x y z]_vvlh = [S, -W, -R].
Mat3 rotation_rsw_to_vvlh();
/// Angular velocity of the local frame of a chief, h/|r|^2, in ECI [rad/s].
Vec3 frame_rate_eci_radps(const StateEci& chief);

/// Relative position/velocity of `deputy` w.r.t. `chief`, in the rotating RSW frame.
/// Layout: [x y z xdot ydot zdot] [m, m/s].
Vec6 relative_rsw_from_eci(const StateEci& chief, const StateEci& deputy);
/// Inverse: deputy ECI state from the chief and an RSW relative state.
StateEci eci_from_relative_rsw(const StateEci& chief, const Vec6& rel_rsw);
/// Same in the rotating VVLH frame.
Vec6 relative_vvlh_from_eci(const StateEci& chief, const StateEci& deputy);
StateEci eci_from_relative_vvlh(const StateEci& chief, const Vec6& rel_vvlh);

}  // namespace evade
