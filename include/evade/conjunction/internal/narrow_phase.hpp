// Internal (not installed): the robust screener's narrow phase on one pair and one grid step
// (src/conjunction/robust_narrow_phase.cpp), as the screening worker and the brute-force
// reference call it: the branch and bound on [a, b] with a rigorous lower bound on the
// distance, the monotonicity tests of the range rate f = rho.rho', and Brent's method on f
// for the TCA (robust_screen.hpp gives the bounds; under J2 they come from arc_bounds.hpp).
// Reference for the radii (eq. 1-2): Wang Xiaoyu, "Space entity collision prediction
// algorithm and self-adaptive simulation step design", J. Air Force Eng. Univ. 7(6), 2006
// (paper 002).
#pragma once

#include <cstddef>
#include <vector>

#include "evade/conjunction/arc_bounds.hpp"
#include "evade/conjunction/ephemeris.hpp"
#include "evade/conjunction/robust_screen.hpp"

namespace evade::conjunction::internal {

// Bounds of every object over the current grid step (ArcBounds: r_lo, r_hi, g, v).
struct PairContext {
  const std::vector<SpaceObject>* objects = nullptr;
  const std::vector<ArcBounds>* bounds = nullptr;
  const ScreenOptions* opt = nullptr;
};

struct Endpoint {
  double t = 0.0;
  StateEci si;
  StateEci sj;
};

// f = rho.rho', rho = r_j - r_i: the range rate times the range.
double range_rate_product(const StateEci& si, const StateEci& sj);

// The positions of a pair at both ends of a grid step of length len_s.
struct StepPositions {
  const Vec3& ri_a;
  const Vec3& rj_a;
  const Vec3& ri_b;
  const Vec3& rj_b;
  double len_s;
};

// The narrow phase's first test on the step from the positions alone: false when the lower
// bound on |rho| over the step exceeds d_ij, so narrow_phase would find nothing (that
// interval is counted in st.refined). The worker passes the grid states' positions (which
// are the exact states', MotionSource::grid_state_at) and computes the exact states only for
// the pairs that pass.
bool may_come_within(std::size_t i, std::size_t j, const StepPositions& s, double d_ij,
                     const PairContext& ctx, ScreenStats& st);

// Narrow phase on one grid step for pair (i, j): branch and bound on [a, b] (see
// robust_screen.hpp). Returns events through `out`.
void narrow_phase(std::size_t i, std::size_t j, const Endpoint& start, const Endpoint& end,
                  const StateEci& gi, const StateEci& gj, double t_grid, double d_ij,
                  const PairContext& ctx, const Ephemeris& eph, StepArcs& arcs,
                  std::vector<Conjunction>& out, ScreenStats& st);

}  // namespace evade::conjunction::internal
