// Robust all-pairs conjunction screening (issue 6; paper 002 eq. 1-2 for the radii):
// apogee/perigee filter (Hoots et al. 1984), swept-box grid broad phase, branch-and-bound
// narrow phase with a rigorous lower bound on the distance, Brent's method on the range
// rate for the TCA. See robust_screen.hpp for the bounds; under J2 every bound comes from
// arc_bounds.hpp (proved in docs/VALIDATION.md, "Robust mode under J2: the no-miss bound").
// This file holds the entry points (screen_robust, screen_robust_part, the merge of parts),
// the per-object bounds over the span and the helpers the parts share
// (internal/screen_support.hpp); the parts are robust_narrow_phase.cpp (narrow phase),
// box_grid.cpp (broad phase grid), screen_worker.cpp (one thread's grid steps),
// step_runner.cpp (blocks of grid steps on threads), screen_options.cpp (ScreenOptions'
// parameter table and checks), brute_force_screen.cpp (screen_brute_force). Paper 002:
// Wang Xiaoyu, "Space entity collision prediction algorithm and self-adaptive simulation
// step design", J. Air Force Eng. Univ. 7(6), 2006.
#include "evade/conjunction/robust_screen.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "evade/conjunction/internal/screen_support.hpp"
#include "evade/conjunction/internal/step_runner.hpp"

namespace evade::conjunction {
namespace internal {

double max_reporting_distance_m(const std::vector<SpaceObject>& objects, const ScreenOptions& opt) {
  double d_max = opt.threshold_m;
  if (opt.include_warning_radius) {
    double lmax = 0.0;
    for (const auto& o : objects) lmax = std::max(lmax, o.size_m + o.pos_error_m);
    d_max = std::max(d_max, opt.warning_multiple * 2.0 * lmax);
  }
  return d_max;
}

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

void sort_events(std::vector<Conjunction>& ev) {
  std::sort(ev.begin(), ev.end(), [](const Conjunction& a, const Conjunction& b) {
    if (a.tca_s != b.tca_s) return a.tca_s < b.tca_s;
    if (a.i != b.i) return a.i < b.i;
    return a.j < b.j;
  });
}

// Near a TCA the distance is d(t) = sqrt(m^2 + v^2 dt^2) = m + v^2 dt^2 / (2 m): within
// dt = sqrt(2 m eps) / v of the TCA it stays within eps of the miss. Two events of one pair
// that close, with misses within eps, are one minimum at the eps = 1 cm resolution the
// screen reports (SGP4's velocity jumps, up to 1e-4 m/s, move the range rate's root of a
// 5 m/s pair passing at 4.8 km by 0.5 s and can make it cross zero twice). The quadratic
// model holds for dt much shorter than an orbit: the window is capped at 60 s.
long merge_repeated_approaches(std::vector<Conjunction>& ev) {
  constexpr double kEpsM = 0.01, kCapS = 60.0;
  std::vector<bool> drop(ev.size(), false);
  long removed = 0;
  for (std::size_t a = 0; a < ev.size(); ++a) {
    if (drop[a]) continue;
    for (std::size_t b = a + 1; b < ev.size() && ev[b].tca_s - ev[a].tca_s <= kCapS; ++b) {
      if (drop[b] || ev[b].i != ev[a].i || ev[b].j != ev[a].j) continue;
      const double m = std::max(std::min(ev[a].miss_m, ev[b].miss_m), 0.0);
      const double v = std::max(ev[a].rel_speed_mps, 1e-9);
      const double window_s = std::min(kCapS, 1e-3 + std::sqrt(2.0 * m * kEpsM) / v);
      if (ev[b].tca_s - ev[a].tca_s > window_s || std::abs(ev[b].miss_m - ev[a].miss_m) > kEpsM) continue;
      const std::size_t worse = ev[b].miss_m < ev[a].miss_m ? a : b;
      drop[worse] = true;
      ++removed;
      if (worse == a) break;
    }
  }
  std::size_t k = 0;
  for (std::size_t a = 0; a < ev.size(); ++a)
    if (!drop[a]) ev[k++] = ev[a];
  ev.resize(k);
  return removed;
}

void add_stats(ScreenStats& into, const ScreenStats& s) {
  into.steps += s.steps;
  into.pairs_checked += s.pairs_checked;
  into.candidates += s.candidates;
  into.refined += s.refined;
  into.root_solves += s.root_solves;
  into.unproven_leaves += s.unproven_leaves;
}

}  // namespace internal

namespace {

using internal::add_stats;
using internal::check_motion_and_primary;
using internal::max_reporting_distance_m;
using internal::ObjectBounds;
using internal::sort_events;
using internal::StepRunner;

// Statistic only (pairs_after_apogee_perigee under J2): an estimate of the J2 short-period
// radius oscillation (~10 km in LEO). The screening itself uses the proven per-step arc
// bounds of arc_bounds.hpp under J2, and the exact conic radii under two-body.
constexpr double kJ2RadiusStatMarginM = 40e3;

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
  const double step = opt.step_s == 0.0 ? auto_step_s(n_objects, opt) : opt.step_s;
  return static_cast<long>(std::ceil(span_s / step - 1e-12));
}

ScreenResult screen_robust_part(const std::vector<SpaceObject>& objects, double span_s,
                                const ScreenOptions& opt_in, int part, int parts) {
  opt_in.validate();
  ScreenOptions opt = opt_in;
  if (opt.step_s == 0.0) opt.step_s = auto_step_s(objects.size(), opt);
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
  res.stats.repeated_roots_merged += internal::merge_repeated_approaches(res.events);
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
  into.stats.repeated_roots_merged += part.stats.repeated_roots_merged +
                                      internal::merge_repeated_approaches(into.events);
}

}  // namespace evade::conjunction
