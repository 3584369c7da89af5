// Narrow phase of the robust screener (issue 6): for one candidate pair on one grid step,
// branch and bound on [a, b] with a rigorous lower bound on the distance (the chord of
// rho(a) -> rho(b) minus A (b-a)^2 / 8), tests that the range rate f = rho.rho' is monotone
// (fast pairs: V_min^2 > R_max A; slow pairs: f' known at both ends and |f''| bounded), and
// Brent's method on f for the TCA (events.hpp). robust_screen.hpp states the bounds; under J2
// (and with a motion source) they come from arc_bounds.hpp (proved in docs/VALIDATION.md,
// "Robust mode under J2: the no-miss bound"). The collision radius R_c and the warning flag
// are eq. 1-2 of Wang Xiaoyu, "Space entity collision prediction algorithm and self-adaptive
// simulation step design", J. Air Force Eng. Univ. 7(6), 2006 (paper 002).
#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "evade/conjunction/arc_bounds.hpp"
#include "evade/conjunction/ephemeris.hpp"
#include "evade/conjunction/internal/narrow_phase.hpp"
#include "evade/dynamics/events.hpp"
#include "evade/dynamics/gravity.hpp"

namespace evade::conjunction::internal {
namespace {

// Distance from the origin to the segment p -> q.
double segment_distance_m(const Vec3& p, const Vec3& q) {
  const Vec3 d = q - p;
  const double dd = d.squaredNorm();
  double s = dd > 0.0 ? -p.dot(d) / dd : 0.0;
  s = std::clamp(s, 0.0, 1.0);
  return (p + s * d).norm();
}

// Constants of one pair in the narrow phase.
struct NarrowPair {
  std::size_t i = 0;
  std::size_t j = 0;
  double a_crude = 0.0;  // g_i + g_j: crude bound on |rho''|
  double r_min = 0.0;    // smaller lower bound on the two radii
  double v_obj = 0.0;    // larger bound on the two objects' speeds
  double d_ij = 0.0;     // reporting distance of the pair
  double rc = 0.0;       // collision radius R_c (eq. 1)
  double p_sum = 0.0;    // eps_i + eps_j: motion's departure from the field (0 without)
  double p_rate_sum = 0.0;  // bound on the rate of that departure
  double v_err_sum = 0.0;   // bound on the error of the relative velocity (motion sources)
};

NarrowPair narrow_pair(std::size_t i, std::size_t j, double d_ij, const PairContext& ctx) {
  const ArcBounds& bi = (*ctx.bounds)[i];
  const ArcBounds& bj = (*ctx.bounds)[j];
  NarrowPair p;
  p.i = i;
  p.j = j;
  p.a_crude = bi.g_max_mps2 + bj.g_max_mps2;
  p.r_min = std::min(bi.r_lo_m, bj.r_lo_m);
  p.v_obj = std::max(bi.v_max_mps, bj.v_max_mps);
  p.d_ij = d_ij;
  p.rc = collision_radius_m((*ctx.objects)[i], (*ctx.objects)[j]);
  p.p_sum = bi.perturbation_mps2 + bj.perturbation_mps2;
  p.p_rate_sum = bi.perturbation_rate_mps3 + bj.perturbation_rate_mps3;
  if (ctx.opt->motion) p.v_err_sum = ctx.opt->motion->velocity_error_mps(i) + ctx.opt->motion->velocity_error_mps(j);
  return p;
}

// States of the pair at any time of the grid step, from the grid states gi, gj at t_grid.
struct PairEphemeris {
  const Ephemeris* eph = nullptr;
  StepArcs* arcs = nullptr;
  std::size_t i = 0;
  std::size_t j = 1;
  const StateEci* gi = nullptr;
  const StateEci* gj = nullptr;
  double t_grid = 0.0;

  Endpoint at(double t) const {
    Endpoint e;
    e.t = t;
    e.si = eph->state_near(*arcs, i, t, *gi, t_grid);
    e.sj = eph->state_near(*arcs, j, t, *gj, t_grid);
    return e;
  }
};

// The bounds of robust_screen.hpp on one interval [a, b] of length len, from the positions
// only: R_max on |rho| and A on |rho''| (the smaller of g_i + g_j and the gravity-gradient
// bound), and the lower bound on |rho| over [a, b] (the chord's distance minus A len^2 / 8).
struct DistanceBound {
  double r_max = 0.0;
  double acc = 0.0;
  double r_seg = 0.0;  // lower bound on the radius along the segment between the objects
  double lower_m = 0.0;
};

DistanceBound distance_bound(const Vec3& rho_a, const Vec3& rho_b, double len, const NarrowPair& p,
                             const ScreenOptions& opt) {
  DistanceBound d;
  const double chord_dev_crude = p.a_crude * len * len / 8.0;
  d.r_max = std::max(rho_a.norm(), rho_b.norm()) + chord_dev_crude;
  // Gravity-gradient bound: |g(r_j) - g(r_i)| <= (2 mu / r^3) |rho| along the segment
  // between the two objects, whose radius is >= r_min - r_max (K(r): arc_bounds.hpp).
  d.acc = p.a_crude;
  d.r_seg = p.r_min - d.r_max;
  if (d.r_seg > 0.0) {
    const double k_grad = gravity_gradient_bound_ps2(d.r_seg, opt.gravity, opt.earth);
    d.acc = std::min(d.acc, k_grad * d.r_max + p.p_sum);
  }
  d.lower_m = segment_distance_m(rho_a, rho_b) - d.acc * len * len / 8.0;
  return d;
}

// Relative motion on one interval [a, b] and its DistanceBound.
struct IntervalGeometry : DistanceBound {
  double len = 0.0;
  Vec3 rho_a, rho_b, vel_a, vel_b;
};

IntervalGeometry interval_geometry(const Endpoint& a, const Endpoint& b, const NarrowPair& p,
                                   const ScreenOptions& opt) {
  IntervalGeometry g;
  g.len = b.t - a.t;
  g.rho_a = a.sj.r_eci_m - a.si.r_eci_m;
  g.rho_b = b.sj.r_eci_m - b.si.r_eci_m;
  g.vel_a = a.sj.v_eci_mps - a.si.v_eci_mps;
  g.vel_b = b.sj.v_eci_mps - b.si.v_eci_mps;
  static_cast<DistanceBound&>(g) = distance_bound(g.rho_a, g.rho_b, g.len, p, opt);
  return g;
}

// What is known of the range rate f = rho.rho' on [a, b]: increasing (at most one - to +
// root) or decreasing (none).
struct Monotonicity {
  bool monotone = false;
  bool decreasing = false;
};

// rho.rho'' at one end of an interval, within +- error: exact from the field for the force
// models; for a motion source, from its accelerations (acceleration_at) when it gives them,
// else the field within |rho| (eps_i + eps_j).
struct EndCurvature {
  double value = 0.0;
  double error = 0.0;
};

EndCurvature end_curvature(const Endpoint& e, const Vec3& rho, const NarrowPair& p,
                           const ScreenOptions& opt) {
  EndCurvature c;
  Vec3 ai, aj;
  double ei = 0.0, ej = 0.0;
  if (opt.motion && opt.motion->acceleration_at(p.i, e.t, ai, ei) &&
      opt.motion->acceleration_at(p.j, e.t, aj, ej)) {
    c.value = rho.dot(aj - ai);
    c.error = rho.norm() * (ei + ej);
    return c;
  }
  auto accel = [&](const Vec3& r) { return accel_eci_mps2(r, opt.gravity, opt.earth); };
  c.value = rho.dot(accel(e.sj.r_eci_m) - accel(e.si.r_eci_m));
  c.error = rho.norm() * p.p_sum;
  return c;
}

Monotonicity range_rate_monotonicity(const Endpoint& a, const Endpoint& b,
                                     const IntervalGeometry& g, const NarrowPair& p,
                                     const ScreenOptions& opt) {
  const double len = g.len;
  const double acc = g.acc;
  const double r_max = g.r_max;
  Monotonicity m;
  // Test 1 (fast pairs): f' >= V_min^2 - R_max A > 0.
  const double v_min = 0.5 * (g.vel_a.norm() + g.vel_b.norm() - acc * len) - p.v_err_sum;
  m.monotone = v_min > 0.0 && v_min * v_min > r_max * acc;
  if (m.monotone || !(g.r_seg > 0.0)) return m;
  // Test 2 (slow pairs): f' = |rho'|^2 + rho.rho'' known at both ends, and
  // |f''| = |3 rho'.rho'' + rho.rho'''| <= B with |rho'''| <= K |rho'| + L |rho| v_max,
  // K and L of arc_bounds.hpp at the segment's radius, v_max the objects' speed bound.
  const double r_seg = g.r_seg;
  const double l_third = gravity_hessian_bound(r_seg, opt.gravity, opt.earth);
  const double k_grad = gravity_gradient_bound_ps2(r_seg, opt.gravity, opt.earth);
  const double v_obj = p.v_obj;
  const double v_rel_max = std::min(g.vel_a.norm(), g.vel_b.norm()) + acc * len + p.v_err_sum;
  const double b_f2 = 3.0 * v_rel_max * acc +
                      r_max * (k_grad * v_rel_max + l_third * r_max * v_obj + p.p_rate_sum);
  const EndCurvature ca = end_curvature(a, g.rho_a, p, opt), cb = end_curvature(b, g.rho_b, p, opt);
  const double dfa = g.vel_a.squaredNorm() + ca.value;
  const double dfb = g.vel_b.squaredNorm() + cb.value;
  // |rho'|^2 from a velocity known to within dv: +- (2 |v| dv + dv^2) at each end.
  const double dv = p.v_err_sum;
  const double v_slack = (2.0 * (g.vel_a.norm() + g.vel_b.norm()) + 2.0 * dv) * dv;
  const double slack = b_f2 * len + ca.error + cb.error + v_slack;
  // On [a, b]: f'(t) >= max(f'(a) - B (t-a), f'(b) - B (b-t)) >= (f'(a) + f'(b) - B len)/2
  // and f'(t) <= (f'(a) + f'(b) + B len)/2.
  m.monotone = dfa + dfb - slack > 0.0;
  m.decreasing = dfa + dfb + slack < 0.0;
  return m;
}

// The root of f in [a, b] (f(a) = fa < 0 <= fb = f(b)) by Brent's method: an event when its
// miss is within d_ij.
void record_closest_approach(const Endpoint& a, const Endpoint& b, double fa, double fb,
                             const NarrowPair& p, const PairEphemeris& pe,
                             const ScreenOptions& opt, std::vector<Conjunction>& out) {
  auto f = [&](double t) {
    const Endpoint e = pe.at(t);
    return range_rate_product(e.si, e.sj);
  };
  const double tca = brent_root(f, a.t, b.t, fa, fb, opt.tca_tol_s, 200);
  const Endpoint e = (tca == b.t) ? b : pe.at(tca);
  const double miss = (e.sj.r_eci_m - e.si.r_eci_m).norm();
  if (miss <= p.d_ij) {
    Conjunction c;
    c.i = p.i;
    c.j = p.j;
    c.tca_s = tca;
    c.miss_m = miss;
    c.rel_speed_mps = (e.sj.v_eci_mps - e.si.v_eci_mps).norm();
    c.collision = miss <= p.rc;
    c.warning = miss <= opt.warning_multiple * p.rc;
    out.push_back(c);
  }
}

}  // namespace

double range_rate_product(const StateEci& si, const StateEci& sj) {
  return (sj.r_eci_m - si.r_eci_m).dot(sj.v_eci_mps - si.v_eci_mps);
}

bool may_come_within(std::size_t i, std::size_t j, const StepPositions& s, double d_ij,
                     const PairContext& ctx, ScreenStats& st) {
  const NarrowPair p = narrow_pair(i, j, d_ij, ctx);
  const Vec3 rho_a = s.rj_a - s.ri_a, rho_b = s.rj_b - s.ri_b;
  if (distance_bound(rho_a, rho_b, s.len_s, p, *ctx.opt).lower_m <= d_ij) return true;
  ++st.refined;  // the narrow phase's first interval, decided here
  return false;
}

// Narrow phase on one grid step for pair (i, j): branch and bound on [a, b] (see
// robust_screen.hpp). Returns events through `out`.
void narrow_phase(std::size_t i, std::size_t j, const Endpoint& start, const Endpoint& end,
                  const StateEci& gi, const StateEci& gj, double t_grid, double d_ij,
                  const PairContext& ctx, const Ephemeris& eph, StepArcs& arcs,
                  std::vector<Conjunction>& out, ScreenStats& st) {
  const ScreenOptions& opt = *ctx.opt;
  const NarrowPair p = narrow_pair(i, j, d_ij, ctx);
  const PairEphemeris pe{&eph, &arcs, i, j, &gi, &gj, t_grid};
  std::vector<std::pair<Endpoint, Endpoint>> stack;
  stack.emplace_back(start, end);
  while (!stack.empty()) {
    auto [a, b] = std::move(stack.back());
    stack.pop_back();
    ++st.refined;
    const IntervalGeometry g = interval_geometry(a, b, p, opt);
    if (g.lower_m > d_ij) continue;
    const Monotonicity m = range_rate_monotonicity(a, b, g, p, opt);
    if (m.decreasing) continue;  // f strictly decreasing: no - to + root, no closest approach
    if (!m.monotone && g.len <= opt.leaf_s) ++st.unproven_leaves;
    if (!m.monotone && g.len > opt.leaf_s) {
      const double tm = a.t + 0.5 * g.len;
      Endpoint mid = pe.at(tm);
      stack.emplace_back(mid, b);
      stack.emplace_back(a, std::move(mid));
      continue;
    }
    const double fa = g.rho_a.dot(g.vel_a);
    const double fb = g.rho_b.dot(g.vel_b);
    if (!(fa < 0.0 && fb >= 0.0)) continue;
    ++st.root_solves;
    record_closest_approach(a, b, fa, fb, p, pe, opt, out);
  }
}

}  // namespace evade::conjunction::internal
