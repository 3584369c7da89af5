// One satellite against a catalog, the orbit-path filter (issue 24): after the perigee/apogee
// filter (primary_prefilter.hpp), an object is set aside when, at every instant of the span,
// where it could be near the primary's orbit plane its radius differs by more than D from
// the primary's radius near the same line: the second filter of Hoots, Crawford & Roehrich
// ("An analytic method to determine future close approaches between satellites", Celestial
// Mechanics 33, 1984), with the planes, nodes and radii bounded from SGP4's own formulas
// over each piece of the span (sgp4::PathBounds, path_bounds.cpp), so that the nodes'
// regression, the apsides' turn, drag and the short-period terms are inside the bounds.
//
// Argument, over a piece [t0, t1] of the span, for the primary p and object j (near-Earth).
// Each position is rho uv(node, incl, su) with node and incl in the ranges of PathBounds;
// take the ranges' midpoints as centre planes, with unit normals Wc_p, Wc_j, and
// eps_b = half the node range + half the inclination range of body b: |W_b - Wc_b| <= eps_b
// and |uv_b - uvc_b(su)| <= eps_b (the normal and the direction move at most by one radian
// per radian of node or inclination). L = Wc_p x Wc_j / R, R = |Wc_p x Wc_j| (sine of the
// centre planes' mutual inclination), s0_b the argument of latitude of L in b's centre plane.
//  a. If |r_j - r_p| <= D at t, then |W_p . r_j| = |W_p . (r_j - r_p)| <= D (r_p lies in its
//     plane), so |Wc_p . uvc_j(su_j)| <= eta_j = D / rho_j_lo + eps_p + eps_j, and
//     Wc_p . uvc_j(s) = +-R sin(s - s0_j): su_j lies within alpha_j = asin(eta_j / R) of s0_j
//     or of s0_j + pi. Likewise su_p within alpha_p of s0_p or s0_p + pi.
//  b. |r_j - r_p| >= min(rho) 2 sin(theta / 2), theta the angle between the directions, so
//     theta <= beta = 2 asin(D / (2 rho_min)). A direction in the arc at s0_b lies within
//     alpha_b + 2 asin(eps_b / 2) of +L, one in the arc at s0_b + pi of -L: when
//     alpha_j + alpha_p + 2 asin(eps_j / 2) + 2 asin(eps_p / 2) + beta < pi, both are in
//     the arcs on the same side of L.
//  c. | |r_j| - |r_p| | <= D: on each side, the radius ranges over the two arcs
//     (sgp4::path_radius_in_arc) must come within D. If neither side's do, the pair is
//     never within D on [t0, t1].
// Pieces that fail the test are halved (down to kPathFilterMinPieceS, at most
// kPathFilterMaxTests tests per object); an object is set aside only when every piece of the
// padded span passes. Deep-space element sets, a deep-space primary, no bound, R <= eta,
// or the side condition failing: kept. Checked against SGP4 in primary_path_filter_test.cpp.
#pragma once

#include <Eigen/Core>

#include "evade/sgp4/sgp4.hpp"

namespace evade::conjunction {

/// Shortest piece of the span the filter tests [s] (node drift over a piece is part of eps).
constexpr double kPathFilterMinPieceS = 1800.0;
/// Most tests of one object (then it is kept: the time filter follows it instead).
constexpr long kPathFilterMaxTests = 64;

/// A body's centre plane over a piece (the middles of its node and inclination ranges): node
/// and in-plane unit vectors n and m (a direction at argument of latitude s is
/// cos s n + sin s m), normal w, and eps (half the node range + half the inclination range:
/// the most the true normal or a direction moves away from the centre's).
struct PathCentrePlane {
  Eigen::Vector3d n, m, w;
  double eps = 0.0;
};
PathCentrePlane path_centre_plane(const sgp4::PathBounds& b) noexcept;

/// What the test of one object found.
struct PathFilterResult {
  bool never_within = false;  ///< proven: never within D over the interval
  long tests = 0;             ///< pieces tested
};

/// Whether object j is proven never within threshold_m of the primary p over
/// [t0_s, t1_s] (seconds from the start of the screen; p_offset_s and j_offset_s: the start
/// of the screen from each element epoch [s]).
PathFilterResult path_never_within(const sgp4::Sgp4Propagator& p, double p_offset_s,
                                   const sgp4::Sgp4Propagator& j, double j_offset_s,
                                   double t0_s, double t1_s, double threshold_m) noexcept;

/// One piece: whether the test above proves no approach within threshold_m over
/// [t0_s, t1_s] (both bounds of the same piece).
bool path_piece_clear(const sgp4::PathBounds& p, const sgp4::PathBounds& j,
                      double threshold_m) noexcept;

}  // namespace evade::conjunction
