// Robust all-pairs conjunction screening (issue 6; paper 002 eq. 1-2 for the radii):
// apogee/perigee filter (Hoots et al. 1984), swept-box grid broad phase, branch-and-bound
// narrow phase with a rigorous lower bound on the distance, Brent's method on the range
// rate for the TCA. See robust_screen.hpp for the bounds; under J2 every bound comes from
// arc_bounds.hpp (proved in docs/VALIDATION.md, "Robust mode under J2: the no-miss bound").
#include "evade/conjunction/robust_screen.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

#include "evade/conjunction/arc_bounds.hpp"
#include "evade/conjunction/ephemeris.hpp"
#include "evade/core/earth_params.hpp"
#include "evade/dynamics/events.hpp"

namespace evade::conjunction {
namespace {

// Statistic only (pairs_after_apogee_perigee under J2): an estimate of the J2 short-period
// radius oscillation (~10 km in LEO). The screening itself uses the proven per-step arc
// bounds of arc_bounds.hpp under J2, and the exact conic radii under two-body.
constexpr double kJ2RadiusStatMarginM = 40e3;

struct ObjectBounds {
  double r_min_m = 0.0;   // lower bound on |r| over the span
  double r_max_m = 0.0;   // upper bound on |r| over the span
  double g_max_mps2 = 0.0;  // upper bound on |r''|
};

// Bounds of every object over the current grid step (ArcBounds: r_lo, r_hi, g, v).
struct PairContext {
  const std::vector<SpaceObject>* objects = nullptr;
  const std::vector<ArcBounds>* bounds = nullptr;
  const ScreenOptions* opt = nullptr;
};

double pair_threshold_m(const SpaceObject& a, const SpaceObject& b, const ScreenOptions& opt) {
  if (!opt.include_warning_radius) return opt.threshold_m;
  return std::max(opt.threshold_m, warning_radius_m(a, b, opt.warning_multiple));
}

// Distance from the origin to the segment p -> q.
double segment_distance_m(const Vec3& p, const Vec3& q) {
  const Vec3 d = q - p;
  const double dd = d.squaredNorm();
  double s = dd > 0.0 ? -p.dot(d) / dd : 0.0;
  s = std::clamp(s, 0.0, 1.0);
  return (p + s * d).norm();
}

struct Endpoint {
  double t = 0.0;
  StateEci si;
  StateEci sj;
};

double range_rate_product(const StateEci& si, const StateEci& sj) {
  return (sj.r_eci_m - si.r_eci_m).dot(sj.v_eci_mps - si.v_eci_mps);
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
  Ephemeris* eph = nullptr;
  std::size_t i = 0;
  std::size_t j = 1;
  const StateEci* gi = nullptr;
  const StateEci* gj = nullptr;
  double t_grid = 0.0;

  Endpoint at(double t) const {
    Endpoint e;
    e.t = t;
    e.si = eph->state_near(i, t, *gi, t_grid);
    e.sj = eph->state_near(j, t, *gj, t_grid);
    return e;
  }
};

// Relative motion on one interval [a, b] and the bounds of robust_screen.hpp: R_max on
// |rho| and A on |rho''| (the smaller of g_i + g_j and the gravity-gradient bound).
struct IntervalGeometry {
  double len = 0.0;
  Vec3 rho_a, rho_b, vel_a, vel_b;
  double r_max = 0.0;
  double acc = 0.0;
  double r_seg = 0.0;  // lower bound on the radius along the segment between the objects
};

IntervalGeometry interval_geometry(const Endpoint& a, const Endpoint& b, const NarrowPair& p,
                                   const ScreenOptions& opt) {
  IntervalGeometry g;
  g.len = b.t - a.t;
  g.rho_a = a.sj.r_eci_m - a.si.r_eci_m;
  g.rho_b = b.sj.r_eci_m - b.si.r_eci_m;
  g.vel_a = a.sj.v_eci_mps - a.si.v_eci_mps;
  g.vel_b = b.sj.v_eci_mps - b.si.v_eci_mps;
  const double chord_dev_crude = p.a_crude * g.len * g.len / 8.0;
  g.r_max = std::max(g.rho_a.norm(), g.rho_b.norm()) + chord_dev_crude;
  // Gravity-gradient bound: |g(r_j) - g(r_i)| <= (2 mu / r^3) |rho| along the segment
  // between the two objects, whose radius is >= r_min - r_max (K(r): arc_bounds.hpp).
  g.acc = p.a_crude;
  g.r_seg = p.r_min - g.r_max;
  if (g.r_seg > 0.0) {
    const double k_grad = gravity_gradient_bound_ps2(g.r_seg, opt.gravity, opt.earth);
    g.acc = std::min(g.acc, k_grad * g.r_max + p.p_sum);
  }
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

// Narrow phase on one grid step for pair (i, j): branch and bound on [a, b] (see
// robust_screen.hpp). Returns events through `out`.
void narrow_phase(std::size_t i, std::size_t j, const Endpoint& start, const Endpoint& end,
                  const StateEci& gi, const StateEci& gj, double t_grid, double d_ij,
                  const PairContext& ctx, Ephemeris& eph, std::vector<Conjunction>& out,
                  ScreenStats& st) {
  const ScreenOptions& opt = *ctx.opt;
  const NarrowPair p = narrow_pair(i, j, d_ij, ctx);
  const PairEphemeris pe{&eph, i, j, &gi, &gj, t_grid};
  std::vector<std::pair<Endpoint, Endpoint>> stack;
  stack.emplace_back(start, end);
  while (!stack.empty()) {
    auto [a, b] = std::move(stack.back());
    stack.pop_back();
    ++st.refined;
    const IntervalGeometry g = interval_geometry(a, b, p, opt);
    const double lower_bound = segment_distance_m(g.rho_a, g.rho_b) - g.acc * g.len * g.len / 8.0;
    if (lower_bound > d_ij) continue;
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

std::vector<ObjectBounds> object_bounds(const std::vector<SpaceObject>& objects,
                                        const ScreenOptions& opt) {
  std::vector<ObjectBounds> b(objects.size());
  const bool j2 = opt.gravity == GravityModel::kTwoBodyJ2;
  for (std::size_t k = 0; k < objects.size(); ++k) {
    const OrbitShape s = orbit_shape(objects[k].state, opt.earth.mu_m3ps2);
    const double margin = j2 ? kJ2RadiusStatMarginM : 0.0;
    b[k].r_min_m = std::max(s.perigee_radius_m - margin, 0.5 * s.perigee_radius_m);
    b[k].r_max_m = s.apogee_radius_m + margin;
    b[k].g_max_mps2 = opt.earth.mu_m3ps2 / (b[k].r_min_m * b[k].r_min_m);
  }
  return b;
}

// Two-body: the conic's radius range holds over the whole span (exact bounds).
std::vector<ArcBounds> conic_bounds(const std::vector<ObjectBounds>& ob, const EarthModel& earth) {
  std::vector<ArcBounds> b(ob.size());
  for (std::size_t k = 0; k < ob.size(); ++k) {
    b[k].r_lo_m = ob[k].r_min_m;
    b[k].r_hi_m = ob[k].r_max_m;
    b[k].g_max_mps2 = ob[k].g_max_mps2;
    b[k].v_max_mps = std::sqrt(2.0 * earth.mu_m3ps2 / ob[k].r_min_m);
  }
  return b;
}

bool apogee_perigee_may_meet(const ArcBounds& a, const ArcBounds& b, double d) {
  return std::max(a.r_lo_m, b.r_lo_m) - std::min(a.r_hi_m, b.r_hi_m) <= d;
}

void sort_events(std::vector<Conjunction>& ev) {
  std::sort(ev.begin(), ev.end(), [](const Conjunction& a, const Conjunction& b) {
    if (a.tca_s != b.tca_s) return a.tca_s < b.tca_s;
    if (a.i != b.i) return a.i < b.i;
    return a.j < b.j;
  });
}

void add_stats(ScreenStats& into, const ScreenStats& s) {
  into.steps += s.steps;
  into.pairs_checked += s.pairs_checked;
  into.candidates += s.candidates;
  into.refined += s.refined;
  into.root_solves += s.root_solves;
  into.unproven_leaves += s.unproven_leaves;
}

constexpr std::int64_t kCellOffset = 1 << 20;
constexpr std::int64_t kCellMax = (1 << 21) - 1;

std::int64_t cell_index(double x, double cell_m) {
  const double q = std::floor(x / cell_m);
  return std::clamp<std::int64_t>(static_cast<std::int64_t>(std::clamp(q, -4e6, 4e6)) + kCellOffset,
                                  0, kCellMax);
}

std::uint64_t cell_key(std::int64_t ix, std::int64_t iy, std::int64_t iz) {
  return (static_cast<std::uint64_t>(ix) << 42) | (static_cast<std::uint64_t>(iy) << 21) |
         static_cast<std::uint64_t>(iz);
}

double max_reporting_distance_m(const std::vector<SpaceObject>& objects, const ScreenOptions& opt) {
  double d_max = opt.threshold_m;
  if (opt.include_warning_radius) {
    double lmax = 0.0;
    for (const auto& o : objects) lmax = std::max(lmax, o.size_m + o.pos_error_m);
    d_max = std::max(d_max, opt.warning_multiple * 2.0 * lmax);
  }
  return d_max;
}

// One worker screens the grid steps [k_begin, k_end). Under J2 its ephemeris first visits
// every grid time before k_begin, so the integrator's steps (and therefore every state and
// event) do not depend on how the steps are split between threads or processes.
struct Worker {
  const std::vector<SpaceObject>* objects;
  const std::vector<ObjectBounds>* bounds;
  const ScreenOptions* opt;
  double span_s;
  long nsteps;
  long k_begin;
  long k_end;
  bool report_progress;
  std::vector<Conjunction> events;
  ScreenStats stats;
  // Per-step scratch.
  std::vector<ArcBounds> step_bounds;
  std::vector<Vec3> lo, hi;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> entries;

  double grid_time(long k) const {
    return k >= nsteps ? span_s : std::min(static_cast<double>(k) * opt->step_s, span_s);
  }

  // Arc bounds of every object on [t_a, t_a + dt] (J2: arc lemma; two-body: the conic).
  void update_step_bounds(const std::vector<StateEci>& sa, const std::vector<StateEci>& sb,
                          double dt) {
    if (opt->gravity != GravityModel::kTwoBodyJ2) return;  // conic bounds, set once
    for (std::size_t i = 0; i < sa.size(); ++i) {
      const PerturbationBound pb = opt->motion ? opt->motion->perturbation(i) : PerturbationBound{};
      step_bounds[i] = arc_bounds(sa[i], sb[i], dt, opt->gravity, opt->earth, pb.accel_mps2);
      step_bounds[i].perturbation_rate_mps3 = pb.rate_mps3;
    }
  }

  // Swept boxes of the step, padded by g h^2/8 + D/2; returns the grid cell size.
  double build_boxes(const std::vector<StateEci>& sa, const std::vector<StateEci>& sb,
                     double dt, double d_max) {
    double cell = 0.0;
    for (std::size_t i = 0; i < sa.size(); ++i) {
      const double pad = step_bounds[i].g_max_mps2 * dt * dt / 8.0 + 0.5 * d_max;
      lo[i] = sa[i].r_eci_m.cwiseMin(sb[i].r_eci_m).array() - pad;
      hi[i] = sa[i].r_eci_m.cwiseMax(sb[i].r_eci_m).array() + pad;
      cell = std::max(cell, (hi[i] - lo[i]).maxCoeff());
    }
    entries.clear();
    for (std::size_t i = 0; i < sa.size(); ++i) {
      const std::int64_t x0 = cell_index(lo[i].x(), cell), x1 = cell_index(hi[i].x(), cell);
      const std::int64_t y0 = cell_index(lo[i].y(), cell), y1 = cell_index(hi[i].y(), cell);
      const std::int64_t z0 = cell_index(lo[i].z(), cell), z1 = cell_index(hi[i].z(), cell);
      for (std::int64_t x = x0; x <= x1; ++x)
        for (std::int64_t y = y0; y <= y1; ++y)
          for (std::int64_t z = z0; z <= z1; ++z)
            entries.emplace_back(cell_key(x, y, z), static_cast<std::uint32_t>(i));
    }
    std::sort(entries.begin(), entries.end());
    return cell;
  }

  // Pairs of one grid step: box overlap, counted once, apogee/perigee, narrow phase.
  void screen_step(const std::vector<StateEci>& sa, const std::vector<StateEci>& sb, double t_a,
                   double t_b, double cell, Ephemeris& eph) {
    const PairContext ctx{objects, &step_bounds, opt};
    for (std::size_t r0 = 0; r0 < entries.size();) {
      std::size_t r1 = r0 + 1;
      while (r1 < entries.size() && entries[r1].first == entries[r0].first) ++r1;
      const std::uint64_t key = entries[r0].first;
      for (std::size_t p = r0; p < r1; ++p) {
        for (std::size_t q = p + 1; q < r1; ++q) {
          ++stats.pairs_checked;
          std::size_t i = entries[p].second, j = entries[q].second;
          if (i > j) std::swap(i, j);
          if (!opt->screens_pair(i, j)) continue;
          if ((lo[i].array() > hi[j].array()).any() || (lo[j].array() > hi[i].array()).any())
            continue;
          const Vec3 corner = lo[i].cwiseMax(lo[j]);
          if (cell_key(cell_index(corner.x(), cell), cell_index(corner.y(), cell),
                       cell_index(corner.z(), cell)) != key)
            continue;  // counted in the cell that holds the overlap's low corner
          const double d_ij = pair_threshold_m((*objects)[i], (*objects)[j], *opt);
          if (!apogee_perigee_may_meet(step_bounds[i], step_bounds[j], d_ij)) continue;
          ++stats.candidates;
          narrow_phase(i, j, Endpoint{t_a, sa[i], sa[j]}, Endpoint{t_b, sb[i], sb[j]}, sa[i],
                       sa[j], t_a, d_ij, ctx, eph, events, stats);
        }
      }
      r0 = r1;
    }
  }

  void run() {
    const std::size_t n = objects->size();
    Ephemeris eph(*objects, opt->gravity, opt->earth, opt->integ, opt->motion);
    const double d_max = max_reporting_distance_m(*objects, *opt);
    step_bounds = conic_bounds(*bounds, opt->earth);
    lo.resize(n);
    hi.resize(n);
    entries.reserve(8 * n);
    std::vector<StateEci> sa, sb;
    const bool replay = opt->gravity == GravityModel::kTwoBodyJ2 && !opt->motion;  // DOP853 steps
    const long k_first = replay ? 0 : k_begin;
    for (long k = k_first; k <= k_begin; ++k) eph.states_at(grid_time(k), sa);
    double t_a = grid_time(k_begin);
    const long progress_every = std::max(1L, (k_end - k_begin) / 100);
    for (long k = k_begin; k < k_end; ++k) {
      const double t_b = grid_time(k + 1);
      eph.states_at(t_b, sb);
      ++stats.steps;
      update_step_bounds(sa, sb, t_b - t_a);
      const double cell = build_boxes(sa, sb, t_b - t_a, d_max);
      screen_step(sa, sb, t_a, t_b, cell, eph);
      std::swap(sa, sb);
      t_a = t_b;
      if (report_progress && opt->progress && ((k - k_begin + 1) % progress_every == 0)) {
        opt->progress(static_cast<double>(k - k_begin + 1) / static_cast<double>(k_end - k_begin));
      }
    }
  }
};

const Param<ScreenOptions> kScreenOptionRows[] = {
    EVADE_PARAM_REAL(ScreenOptions, threshold_m, "m", 0.0, 1e8, false,
                     "D: report every closest approach with miss <= max(D, N R_c)"),
    EVADE_PARAM_REAL(ScreenOptions, step_s, "s", 0.0, 1e5, false,
                     "grid step h of the broad phase (0: auto_step_s(N))"),
    EVADE_PARAM_REAL(ScreenOptions, leaf_s, "s", 1e-6, 1e5, false,
                     "smallest subdivision of the narrow phase"),
};

}  // namespace

ParamTable<ScreenOptions> screen_options_params() noexcept {
  return make_param_table(kScreenOptionRows);
}

void ScreenOptions::validate() const {
  const std::string bad = validate_params(screen_options_params(), *this, "robust.");
  if (!bad.empty()) throw std::invalid_argument(bad);
  auto fail = [](const char* key, double v, const char* range) {
    std::ostringstream os;
    os << "screen." << key << " = " << v << " outside " << range;
    throw std::invalid_argument(os.str());
  };
  if (!(warning_multiple > 1.0) || !std::isfinite(warning_multiple))
    fail("warning_multiple", warning_multiple, "(1, inf)");
  if (!(tca_tol_s > 0.0) || !std::isfinite(tca_tol_s)) fail("tca_tol_s", tca_tol_s, "(0, inf)");
  if (threads < 1 || threads > 256) fail("threads", threads, "[1, 256]");
  if (primary < -1) fail("primary", static_cast<double>(primary), "[-1, objects)");
  if (motion) {
    const EarthModel m = motion->reference_earth();
    if (gravity != GravityModel::kTwoBodyJ2 || m.mu_m3ps2 != earth.mu_m3ps2 || m.re_m != earth.re_m ||
        m.j2 != earth.j2) {
      throw std::invalid_argument(
          "screen.motion: the motion's perturbation bound is measured against two-body + J2 with "
          "its reference Earth model: set gravity = two_body_j2 and earth = reference_earth()");
    }
  }
  const std::string bad_earth = validate_params(earth_params(), earth, "earth.");
  if (!bad_earth.empty()) throw std::invalid_argument(bad_earth);
  integ.validate();
}

double auto_step_s(std::size_t n_objects) {
  const double n = static_cast<double>(std::max<std::size_t>(n_objects, 1));
  return std::clamp(60.0 * std::cbrt(10000.0 / n), 10.0, 120.0);
}

namespace {

// Statistic only: pairs whose radius ranges come within D_max of each other, counted in
// O(N log N) (sorted perigee radii, binary search) rather than over all N^2 pairs.
long count_apogee_perigee_pairs(const std::vector<ObjectBounds>& bounds, double d_max) {
  const std::size_t n = bounds.size();
  std::vector<std::pair<double, double>> ranges(n);
  for (std::size_t i = 0; i < n; ++i) ranges[i] = {bounds[i].r_min_m, bounds[i].r_max_m};
  std::sort(ranges.begin(), ranges.end());
  long count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double reach = ranges[i].second + d_max;
    const auto last = std::upper_bound(ranges.begin() + static_cast<long>(i) + 1, ranges.end(),
                                       std::make_pair(reach, std::numeric_limits<double>::infinity()));
    count += last - (ranges.begin() + static_cast<long>(i) + 1);
  }
  return count;
}

void run_workers(std::vector<Worker>& workers) {
  if (workers.size() == 1) {
    workers[0].run();
    return;
  }
  std::vector<std::thread> threads;
  std::vector<std::exception_ptr> errors(workers.size());
  for (std::size_t w = 0; w < workers.size(); ++w) {
    threads.emplace_back([&workers, &errors, w]() {
      try {
        workers[w].run();
      } catch (...) {
        errors[w] = std::current_exception();
      }
    });
  }
  for (auto& t : threads) t.join();
  for (auto& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace

namespace {

void check_motion_and_primary(const std::vector<SpaceObject>& objects, const ScreenOptions& opt) {
  if (opt.motion && opt.motion->size() != objects.size()) {
    throw std::invalid_argument("screen.motion: " + std::to_string(opt.motion->size()) +
                                " moving objects for " + std::to_string(objects.size()) + " objects");
  }
  if (opt.primary >= static_cast<long>(objects.size())) {
    throw std::invalid_argument("screen.primary = " + std::to_string(opt.primary) + " outside [-1, " +
                                std::to_string(objects.size()) + ")");
  }
}

// Statistic: with a primary, the objects whose radius range comes within d_max of its own.
long count_primary_pairs(const std::vector<ObjectBounds>& bounds, long primary, double d_max) {
  const ObjectBounds& p = bounds[static_cast<std::size_t>(primary)];
  long count = 0;
  for (std::size_t k = 0; k < bounds.size(); ++k) {
    if (static_cast<long>(k) == primary) continue;
    if (std::max(p.r_min_m, bounds[k].r_min_m) - std::min(p.r_max_m, bounds[k].r_max_m) <= d_max) ++count;
  }
  return count;
}

}  // namespace

long screen_grid_steps(double span_s, const ScreenOptions& opt, std::size_t n_objects) {
  const double step = opt.step_s == 0.0 ? auto_step_s(n_objects) : opt.step_s;
  return static_cast<long>(std::ceil(span_s / step - 1e-12));
}

ScreenResult screen_robust_part(const std::vector<SpaceObject>& objects, double span_s,
                                const ScreenOptions& opt_in, int part, int parts) {
  opt_in.validate();
  ScreenOptions opt = opt_in;
  if (opt.step_s == 0.0) opt.step_s = auto_step_s(objects.size());
  if (!(span_s > 0.0) || !std::isfinite(span_s)) {
    throw std::invalid_argument("span_s = " + std::to_string(span_s) + " outside (0, inf)");
  }
  if (parts < 1 || part < 0 || part >= parts) {
    throw std::invalid_argument("screen part " + std::to_string(part) + " of " +
                                std::to_string(parts) + " outside [0, parts)");
  }
  validate_objects(objects, opt.earth);
  check_motion_and_primary(objects, opt);
  ScreenResult res;
  const std::vector<ObjectBounds> bounds = object_bounds(objects, opt);
  if (part == 0) {
    const double d_max = max_reporting_distance_m(objects, opt);
    res.stats.pairs_after_apogee_perigee = opt.primary >= 0
                                               ? count_primary_pairs(bounds, opt.primary, d_max)
                                               : count_apogee_perigee_pairs(bounds, d_max);
  }
  if (objects.size() < 2) return res;
  const long nsteps = screen_grid_steps(span_s, opt, objects.size());
  const long p_begin = nsteps * part / parts;
  const long p_end = nsteps * (part + 1) / parts;
  const long p_steps = p_end - p_begin;
  const int nthreads = static_cast<int>(std::min<long>(opt.threads, std::max(1L, p_steps)));
  std::vector<Worker> workers;
  workers.reserve(nthreads);
  for (int w = 0; w < nthreads; ++w) {
    const long k0 = p_begin + p_steps * w / nthreads;
    const long k1 = p_begin + p_steps * (w + 1) / nthreads;
    workers.push_back(Worker{&objects, &bounds, &opt, span_s, nsteps, k0, k1, w == 0, {}, {},
                             {}, {}, {}, {}});
  }
  if (p_steps > 0) run_workers(workers);
  for (auto& w : workers) {
    res.events.insert(res.events.end(), w.events.begin(), w.events.end());
    add_stats(res.stats, w.stats);
  }
  sort_events(res.events);
  return res;
}

ScreenResult screen_robust(const std::vector<SpaceObject>& objects, double span_s,
                           const ScreenOptions& opt) {
  return screen_robust_part(objects, span_s, opt, 0, 1);
}

void merge_screen_results(ScreenResult& into, const ScreenResult& part) {
  into.events.insert(into.events.end(), part.events.begin(), part.events.end());
  add_stats(into.stats, part.stats);
  into.stats.pairs_after_apogee_perigee += part.stats.pairs_after_apogee_perigee;
  sort_events(into.events);
}

ScreenResult screen_brute_force(const std::vector<SpaceObject>& objects, double span_s,
                                double sample_step_s, const ScreenOptions& opt) {
  opt.validate();
  if (!(sample_step_s > 0.0) || !std::isfinite(sample_step_s)) {
    throw std::invalid_argument("sample_step_s outside (0, inf)");
  }
  validate_objects(objects, opt.earth);
  ScreenResult res;
  const std::size_t n = objects.size();
  if (n < 2) return res;
  check_motion_and_primary(objects, opt);
  Ephemeris eph(objects, opt.gravity, opt.earth, opt.integ, opt.motion);
  const long nsteps = static_cast<long>(std::ceil(span_s / sample_step_s - 1e-12));
  std::vector<StateEci> prev, cur;
  std::vector<double> f_prev(n * n, 0.0);
  double t_prev = 0.0;
  eph.states_at(0.0, prev);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) f_prev[i * n + j] = range_rate_product(prev[i], prev[j]);
  for (long k = 1; k <= nsteps; ++k) {
    const double t = (k == nsteps) ? span_s : static_cast<double>(k) * sample_step_s;
    eph.states_at(t, cur);
    ++res.stats.steps;
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = i + 1; j < n; ++j) {
        if (!opt.screens_pair(i, j)) continue;
        ++res.stats.pairs_checked;
        const double fc = range_rate_product(cur[i], cur[j]);
        double& fp = f_prev[i * n + j];
        if (fp < 0.0 && fc >= 0.0) {
          ++res.stats.root_solves;
          const StateEci gi = prev[i], gj = prev[j];
          auto f = [&](double tt) {
            return range_rate_product(eph.state_near(i, tt, gi, t_prev), eph.state_near(j, tt, gj, t_prev));
          };
          const double tca = brent_root(f, t_prev, t, fp, fc, opt.tca_tol_s, 200);
          const StateEci si = eph.state_near(i, tca, gi, t_prev);
          const StateEci sj = eph.state_near(j, tca, gj, t_prev);
          const double miss = (sj.r_eci_m - si.r_eci_m).norm();
          const double d_ij = pair_threshold_m(objects[i], objects[j], opt);
          if (miss <= d_ij) {
            const double rc = collision_radius_m(objects[i], objects[j]);
            res.events.push_back(Conjunction{i, j, tca, miss, (sj.v_eci_mps - si.v_eci_mps).norm(),
                                             miss <= rc, miss <= opt.warning_multiple * rc});
          }
        }
        fp = fc;
      }
    }
    std::swap(prev, cur);
    t_prev = t;
  }
  sort_events(res.events);
  return res;
}

}  // namespace evade::conjunction
