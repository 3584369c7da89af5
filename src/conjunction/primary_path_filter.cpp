// The orbit-path filter of one satellite against a catalog
// (include/evade/conjunction/primary_path_filter.hpp gives the argument).
#include "evade/conjunction/primary_path_filter.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace evade::conjunction {
namespace {

constexpr double kPi = 3.141592653589793;

// The angle a chord of length eps subtends on the unit sphere (pi when eps >= 2).
double chord_angle(double eps) { return 2.0 * std::asin(std::min(1.0, 0.5 * eps)); }

// Step c of the argument: whether the radius ranges over the two arcs at s0 + side stay
// more than D apart (false also when a range has no bound).
bool side_apart(const sgp4::PathBounds& p, double s0_p, double a_p, const sgp4::PathBounds& j,
                double s0_j, double a_j, double side, double d) {
  const sgp4::RadiusBounds rp = sgp4::path_radius_in_arc(p, s0_p + side - a_p, s0_p + side + a_p);
  const sgp4::RadiusBounds rj = sgp4::path_radius_in_arc(j, s0_j + side - a_j, s0_j + side + a_j);
  if (!rp.bounded || !rj.bounded) return false;
  return rj.min_m > rp.max_m + d || rj.max_m < rp.min_m - d;
}

}  // namespace

PathCentrePlane path_centre_plane(const sgp4::PathBounds& b) noexcept {
  const double node = 0.5 * (b.node_lo_rad + b.node_hi_rad);
  const double incl = 0.5 * (b.incl_lo_rad + b.incl_hi_rad);
  const double so = std::sin(node), co = std::cos(node), si = std::sin(incl), ci = std::cos(incl);
  PathCentrePlane c;
  c.n = {co, so, 0.0};
  c.m = {-so * ci, co * ci, si};
  c.w = {so * si, -co * si, ci};
  c.eps = 0.5 * (b.node_hi_rad - b.node_lo_rad) + 0.5 * (b.incl_hi_rad - b.incl_lo_rad);
  return c;
}

bool path_piece_clear(const sgp4::PathBounds& p, const sgp4::PathBounds& j,
                      double threshold_m) noexcept {
  if (!p.bounded || !j.bounded || !(p.radius.min_m > 0.0) || !(j.radius.min_m > 0.0)) return false;
  const PathCentrePlane cp = path_centre_plane(p), cj = path_centre_plane(j);
  const Eigen::Vector3d cross = cp.w.cross(cj.w);
  const double r = cross.norm();
  const double d = threshold_m;
  const double eta_j = d / j.radius.min_m + cp.eps + cj.eps;
  const double eta_p = d / p.radius.min_m + cp.eps + cj.eps;
  if (!(eta_j < r) || !(eta_p < r)) return false;  // (a): the arcs would cover everything
  const Eigen::Vector3d l = cross / r;
  const double s0_j = std::atan2(l.dot(cj.m), l.dot(cj.n));
  const double s0_p = std::atan2(l.dot(cp.m), l.dot(cp.n));
  const double a_j = std::asin(eta_j / r), a_p = std::asin(eta_p / r);
  const double rho_min = std::min(p.radius.min_m, j.radius.min_m);
  const double beta = 2.0 * std::asin(std::min(1.0, d / (2.0 * rho_min)));
  // (b): opposite sides are too far apart to be within D.
  if (!(a_j + a_p + chord_angle(cj.eps) + chord_angle(cp.eps) + beta < kPi)) return false;
  // (c) on both sides.
  return side_apart(p, s0_p, a_p, j, s0_j, a_j, 0.0, d) && side_apart(p, s0_p, a_p, j, s0_j, a_j, kPi, d);
}

PathFilterResult path_never_within(const sgp4::Sgp4Propagator& p, double p_offset_s,
                                   const sgp4::Sgp4Propagator& j, double j_offset_s,
                                   double t0_s, double t1_s, double threshold_m) noexcept {
  PathFilterResult res;
  if (p.deep_space() || j.deep_space() || !(t0_s < t1_s)) return res;
  // Depth-first over the pieces, halving those that fail: at most one pending piece per
  // level (each halving pushes two and the next pass pops one), levels < 64 for any span
  // above kPathFilterMinPieceS / 2^62.
  struct Piece {
    double t0, t1;
  };
  std::array<Piece, 64> stack{};
  std::size_t top = 0;
  stack[top++] = {t0_s, t1_s};
  while (top > 0) {
    if (res.tests >= kPathFilterMaxTests) return res;
    const Piece piece = stack[--top];
    ++res.tests;
    const sgp4::PathBounds bp = p.path_bounds((piece.t0 + p_offset_s) / 60.0, (piece.t1 + p_offset_s) / 60.0);
    const sgp4::PathBounds bj = j.path_bounds((piece.t0 + j_offset_s) / 60.0, (piece.t1 + j_offset_s) / 60.0);
    if (path_piece_clear(bp, bj, threshold_m)) continue;
    const double mid = 0.5 * (piece.t0 + piece.t1);
    if (piece.t1 - piece.t0 < 2.0 * kPathFilterMinPieceS || top + 2 > stack.size()) return res;
    stack[top++] = {mid, piece.t1};
    stack[top++] = {piece.t0, mid};
  }
  res.never_within = true;
  return res;
}

}  // namespace evade::conjunction
