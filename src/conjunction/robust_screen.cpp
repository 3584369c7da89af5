// Robust all-pairs conjunction screening (issue 6; paper 002 eq. 1-2 for the radii):
// apogee/perigee filter (Hoots et al. 1984), swept-box grid broad phase, branch-and-bound
// narrow phase with a rigorous lower bound on the distance, Brent's method on the range
// rate for the TCA. See robust_screen.hpp for the bounds; under J2 every bound comes from
// arc_bounds.hpp (proved in docs/VALIDATION.md, "Robust mode under J2: the no-miss bound").
#include "evade/conjunction/robust_screen.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <exception>
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

double max_reporting_distance_m(const std::vector<SpaceObject>& objects, const ScreenOptions& opt) {
  double d_max = opt.threshold_m;
  if (opt.include_warning_radius) {
    double lmax = 0.0;
    for (const auto& o : objects) lmax = std::max(lmax, o.size_m + o.pos_error_m);
    d_max = std::max(d_max, opt.warning_multiple * 2.0 * lmax);
  }
  return d_max;
}

// Cell of coordinate x in a uniform grid of cell size cell_m (the same cells at every step:
// floor(x / cell), clamped).
std::int64_t cell_index(double x, double cell_m) {
  return static_cast<std::int64_t>(std::clamp(std::floor(x / cell_m), -4e6, 4e6));
}

// Stable LSD radix sort of (cell key << 32 | object) by the key's low `key_bits` bits; the
// entries come in object order, so each cell's objects stay in increasing order (the order
// std::sort of the (key, object) pairs gives).
void radix_sort_by_key(std::vector<std::uint64_t>& v, std::vector<std::uint64_t>& tmp,
                       int key_bits) {
  constexpr int kDigit = 11;
  constexpr std::size_t kBuckets = std::size_t{1} << kDigit;
  tmp.resize(v.size());
  std::vector<std::uint32_t> count(kBuckets);
  for (int shift = 32; shift < 32 + key_bits; shift += kDigit) {
    std::fill(count.begin(), count.end(), 0u);
    for (std::uint64_t e : v) ++count[(e >> shift) & (kBuckets - 1)];
    std::uint32_t sum = 0;
    for (std::uint32_t& c : count) {
      const std::uint32_t n = c;
      c = sum;
      sum += n;
    }
    for (std::uint64_t e : v) tmp[count[(e >> shift) & (kBuckets - 1)]++] = e;
    v.swap(tmp);
  }
}

// The swept boxes of one grid step in a uniform grid of cells as large as the largest box
// (each box touches at most 2 cells per axis): for each object its box and its lowest cell,
// and the (cell, object) entries sorted by cell.
// One object's box and lowest cell (relative to the origin), in one cache line.
struct alignas(64) GridBox {
  double lo[3];
  double hi[3];
  std::int32_t cell[3];
};

struct BoxGrid {
  double cell_m = 0.0;
  std::int64_t origin[3] = {0, 0, 0};  // lowest cell on each axis
  std::int64_t extent[3] = {1, 1, 1};  // cells on each axis
  std::vector<Vec3> lo, hi;
  std::vector<GridBox> box;
  std::vector<std::uint64_t> entries, scratch;

  std::uint64_t key(std::int64_t x, std::int64_t y, std::int64_t z) const {
    return static_cast<std::uint64_t>((x * extent[1] + y) * extent[2] + z);
  }

  void build(std::size_t n) {
    double cell = 0.0;
    Vec3 lo_min = lo[0], hi_max = hi[0];
    for (std::size_t i = 0; i < n; ++i) {
      cell = std::max(cell, (hi[i] - lo[i]).maxCoeff());
      lo_min = lo_min.cwiseMin(lo[i]);
      hi_max = hi_max.cwiseMax(hi[i]);
    }
    cell_m = cell;
    for (int a = 0; a < 3; ++a) {
      origin[a] = cell_index(lo_min[a], cell);
      extent[a] = cell_index(hi_max[a], cell) - origin[a] + 1;
    }
    box.resize(n);
    entries.clear();
    for (std::size_t i = 0; i < n; ++i) {
      std::int64_t c0[3], c1[3];
      GridBox& b = box[i];
      for (int a = 0; a < 3; ++a) {
        c0[a] = cell_index(lo[i][a], cell) - origin[a];
        c1[a] = cell_index(hi[i][a], cell) - origin[a];
        b.lo[a] = lo[i][a];
        b.hi[a] = hi[i][a];
        b.cell[a] = static_cast<std::int32_t>(c0[a]);
      }
      for (std::int64_t x = c0[0]; x <= c1[0]; ++x)
        for (std::int64_t y = c0[1]; y <= c1[1]; ++y)
          for (std::int64_t z = c0[2]; z <= c1[2]; ++z)
            entries.push_back(key(x, y, z) << 32 | static_cast<std::uint64_t>(i));
    }
    const std::uint64_t max_key = key(extent[0] - 1, extent[1] - 1, extent[2] - 1);
    int bits = 1;
    while (bits < 32 && (max_key >> bits) != 0) ++bits;
    if ((max_key >> 31) != 0) {
      std::sort(entries.begin(), entries.end(), [](std::uint64_t p, std::uint64_t q) {
        return p < q;
      });  // more than 2^31 cells: keys overflow the radix layout, fall back (never in practice)
    } else {
      radix_sort_by_key(entries, scratch, bits);
    }
  }
};

// One thread's screening of whole grid steps: arc bounds, boxes, pairs, narrow phase; its
// events and statistics accumulate here.
struct Worker {
  const std::vector<SpaceObject>* objects;
  const ScreenOptions* opt;
  const Ephemeris* eph;
  double d_max;
  StepArcs arcs;
  std::vector<Conjunction> events;
  ScreenStats stats;
  std::vector<ArcBounds> step_bounds;  // conic bounds (two-body), or per step (J2)
  BoxGrid grid;
  std::vector<double> size_m;  // L_i + dR_i of every object (eq. 1)
  // One cell's members and their boxes, one array per coordinate, for the pair loop.
  std::vector<std::uint32_t> cell_obj;
  std::array<std::vector<double>, 6> cell_box;  // lo x, y, z, hi x, y, z
  std::array<std::vector<std::int32_t>, 3> cell_low;  // lowest cell x, y, z
  std::vector<unsigned char> overlap;

  // D_ij = max(D, N R_c(i, j)) (pair_threshold_m from the per-object sums).
  double pair_threshold(std::size_t i, std::size_t j) const {
    if (!opt->include_warning_radius) return opt->threshold_m;
    return std::max(opt->threshold_m, opt->warning_multiple * (size_m[i] + size_m[j]));
  }

  // Arc bounds of every object on [t_a, t_a + dt] (J2: arc lemma; two-body: the conic).
  void update_step_bounds(const StateEci* sa, const StateEci* sb, double dt) {
    if (opt->gravity != GravityModel::kTwoBodyJ2) return;  // conic bounds, set once
    for (std::size_t i = 0; i < step_bounds.size(); ++i) {
      const PerturbationBound pb = opt->motion ? opt->motion->perturbation(i) : PerturbationBound{};
      step_bounds[i] = arc_bounds(sa[i], sb[i], dt, opt->gravity, opt->earth, pb.accel_mps2);
      step_bounds[i].perturbation_rate_mps3 = pb.rate_mps3;
    }
  }

  // Swept boxes of the step, padded by g h^2/8 + D/2, in the grid.
  void build_boxes(const StateEci* sa, const StateEci* sb, double dt) {
    const std::size_t n = step_bounds.size();
    grid.lo.resize(n);
    grid.hi.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double pad = step_bounds[i].g_max_mps2 * dt * dt / 8.0 + 0.5 * d_max;
      grid.lo[i] = sa[i].r_eci_m.cwiseMin(sb[i].r_eci_m).array() - pad;
      grid.hi[i] = sa[i].r_eci_m.cwiseMax(sb[i].r_eci_m).array() + pad;
    }
    grid.build(n);
  }

  // The pairs of one cell: box overlap, counted once (in the cell of the overlap's low
  // corner), apogee/perigee, narrow phase.
  void screen_cell(std::uint64_t key, const StateEci* sa, const StateEci* sb, double t_a,
                   double t_b) {
    const auto cz = static_cast<std::int32_t>(key % static_cast<std::uint64_t>(grid.extent[2]));
    const std::uint64_t xy = key / static_cast<std::uint64_t>(grid.extent[2]);
    const auto cy = static_cast<std::int32_t>(xy % static_cast<std::uint64_t>(grid.extent[1]));
    const auto cx = static_cast<std::int32_t>(xy / static_cast<std::uint64_t>(grid.extent[1]));
    const PairContext ctx{objects, &step_bounds, opt};
    const std::size_t m = cell_obj.size();
    const double* lx = cell_box[0].data();
    const double* ly = cell_box[1].data();
    const double* lz = cell_box[2].data();
    const double* hx = cell_box[3].data();
    const double* hy = cell_box[4].data();
    const double* hz = cell_box[5].data();
    overlap.resize(m);
    unsigned char* ov = overlap.data();
    for (std::size_t p = 0; p < m; ++p) {
      stats.pairs_checked += static_cast<long>(m - p - 1);
      // Box overlap of p with every later member (branch-free, so the compiler vectorizes it).
      for (std::size_t q = p + 1; q < m; ++q) {
        ov[q] = static_cast<unsigned char>((lx[p] <= hx[q]) & (lx[q] <= hx[p]) & (ly[p] <= hy[q]) &
                                           (ly[q] <= hy[p]) & (lz[p] <= hz[q]) & (lz[q] <= hz[p]));
      }
      for (std::size_t q = p + 1; q < m; ++q) {
        if (!ov[q] || !opt->screens_pair(cell_obj[p], cell_obj[q])) continue;
        if (std::max(cell_low[0][p], cell_low[0][q]) != cx ||
            std::max(cell_low[1][p], cell_low[1][q]) != cy ||
            std::max(cell_low[2][p], cell_low[2][q]) != cz)
          continue;  // counted in the cell that holds the overlap's low corner
        const std::size_t i = cell_obj[p], j = cell_obj[q];  // i < j (cells keep object order)
        const double d_ij = pair_threshold(i, j);
        if (!apogee_perigee_may_meet(step_bounds[i], step_bounds[j], d_ij)) continue;
        ++stats.candidates;
        narrow_phase(i, j, Endpoint{t_a, sa[i], sa[j]}, Endpoint{t_b, sb[i], sb[j]}, sa[i], sa[j],
                     t_a, d_ij, ctx, *eph, arcs, events, stats);
      }
    }
  }

  // Grid step [t_a, t_b] with the states of every object at both ends.
  void screen_step(const StateEci* sa, const StateEci* sb, double t_a, double t_b) {
    ++stats.steps;
    update_step_bounds(sa, sb, t_b - t_a);
    build_boxes(sa, sb, t_b - t_a);
    const std::vector<std::uint64_t>& e = grid.entries;
    for (std::size_t r0 = 0; r0 < e.size();) {
      const std::uint64_t key = e[r0] >> 32;
      cell_obj.clear();
      for (auto& c : cell_box) c.clear();
      for (auto& c : cell_low) c.clear();
      std::size_t r1 = r0;
      for (; r1 < e.size() && (e[r1] >> 32) == key; ++r1) {
        const auto i = static_cast<std::uint32_t>(e[r1] & 0xffffffffu);
        const GridBox& b = grid.box[i];
        cell_obj.push_back(i);
        for (std::size_t a = 0; a < 3; ++a) {
          cell_box[a].push_back(b.lo[a]);
          cell_box[a + 3].push_back(b.hi[a]);
          cell_low[a].push_back(b.cell[a]);
        }
      }
      if (r1 - r0 > 1) screen_cell(key, sa, sb, t_a, t_b);
      r0 = r1;
    }
  }
};

// Runs body(t) on threads t = 0 .. nthreads - 1 (t = 0 on the calling thread); rethrows the
// first exception.
template <class Body>
void run_parallel(int nthreads, const Body& body) {
  if (nthreads == 1) {
    body(0);
    return;
  }
  std::vector<std::thread> threads;
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(nthreads));
  for (int t = 1; t < nthreads; ++t) {
    threads.emplace_back([&body, &errors, t]() {
      try {
        body(t);
      } catch (...) {
        errors[static_cast<std::size_t>(t)] = std::current_exception();
      }
    });
  }
  try {
    body(0);
  } catch (...) {
    errors[0] = std::current_exception();
  }
  for (auto& th : threads) th.join();
  for (auto& e : errors)
    if (e) std::rethrow_exception(e);
}

// The grid steps [k_begin, k_end) of a screening, by blocks of grid steps: the threads first
// advance every object (split by objects) through the block's grid times, then screen the
// block's steps (split by steps). Each object's integrator visits every grid time from
// t = 0 (J2), so its states, and therefore every event, do not depend on how the steps are
// split between threads or processes.
class StepRunner {
 public:
  StepRunner(const std::vector<SpaceObject>& objects, const std::vector<ObjectBounds>& bounds,
             const ScreenOptions& opt, double span_s, long nsteps, int nthreads)
      : objects_(objects), opt_(opt), span_s_(span_s), nsteps_(nsteps), nthreads_(nthreads),
        eph_(objects, opt.gravity, opt.earth, opt.integ, opt.motion) {
    const double d_max = max_reporting_distance_m(objects, opt);
    const std::vector<ArcBounds> conic = conic_bounds(bounds, opt.earth);
    std::vector<double> size_m(objects.size());
    for (std::size_t i = 0; i < objects.size(); ++i)
      size_m[i] = objects[i].size_m + objects[i].pos_error_m;
    for (int t = 0; t < nthreads; ++t) {
      workers_.push_back(Worker{&objects, &opt, &eph_, d_max, eph_.make_arcs(), {}, {}, conic, {},
                                size_m, {}, {}, {}, {}});
    }
  }

  void run(long k_begin, long k_end, ScreenResult& res) {
    const std::size_t n = objects_.size();
    // Grid states of one block: rows_[m] at grid time k0 + m.
    const long block = std::clamp<long>(static_cast<long>(1'000'000 / std::max<std::size_t>(n, 1)), 4, 64);
    rows_.assign(static_cast<std::size_t>(block) + 1, std::vector<StateEci>(n));
    // J2: every grid time before k_begin (the integrators' steps end on each of them).
    const bool replay = opt_.gravity == GravityModel::kTwoBodyJ2 && !opt_.motion;  // DOP853 steps
    const long k_first = replay ? 0 : k_begin;
    advance(k_first, k_begin, k_begin);
    for (long k0 = k_begin; k0 < k_end; k0 += block) {
      const long k1 = std::min(k_end, k0 + block);
      if (k0 != k_begin) std::swap(rows_[0], rows_[static_cast<std::size_t>(block)]);
      advance(k0 + 1, k1, k0);
      screen_steps(k0, k1);
      if (opt_.progress) {
        opt_.progress(static_cast<double>(k1 - k_begin) / static_cast<double>(k_end - k_begin));
      }
    }
    for (auto& w : workers_) {
      res.events.insert(res.events.end(), w.events.begin(), w.events.end());
      add_stats(res.stats, w.stats);
    }
  }

 private:
  double grid_time(long k) const {
    return k >= nsteps_ ? span_s_ : std::min(static_cast<double>(k) * opt_.step_s, span_s_);
  }

  // Every object through grid times k_from .. k_to; the states at grid time k go to
  // rows_[k - k_row0] when k >= k_row0 (objects split between threads in chunks).
  void advance(long k_from, long k_to, long k_row0) {
    if (k_from > k_to) return;
    constexpr std::size_t kChunk = 64;
    const std::size_t n = objects_.size();
    std::atomic<std::size_t> next{0};
    run_parallel(nthreads_, [&](int) {
      for (std::size_t b = next.fetch_add(kChunk); b < n; b = next.fetch_add(kChunk)) {
        const std::size_t e = std::min(n, b + kChunk);
        for (long k = k_from; k <= k_to; ++k) {
          std::vector<StateEci>& row = rows_[static_cast<std::size_t>(std::max(k - k_row0, 0L))];
          eph_.states_at(grid_time(k), b, e, row.data());
        }
      }
    });
  }

  // Grid steps [k0, k1) from rows_[0 .. k1 - k0] (steps split between threads).
  void screen_steps(long k0, long k1) {
    std::atomic<long> next{k0};
    run_parallel(nthreads_, [&](int t) {
      Worker& w = workers_[static_cast<std::size_t>(t)];
      for (long k = next.fetch_add(1); k < k1; k = next.fetch_add(1)) {
        const std::size_t m = static_cast<std::size_t>(k - k0);
        w.screen_step(rows_[m].data(), rows_[m + 1].data(), grid_time(k), grid_time(k + 1));
      }
    });
  }

  const std::vector<SpaceObject>& objects_;
  const ScreenOptions& opt_;
  double span_s_;
  long nsteps_;
  int nthreads_;
  Ephemeris eph_;
  std::vector<Worker> workers_;
  std::vector<std::vector<StateEci>> rows_;
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
  if (p_steps > 0) {
    StepRunner runner(objects, bounds, opt, span_s, nsteps, nthreads);
    runner.run(p_begin, p_end, res);
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
