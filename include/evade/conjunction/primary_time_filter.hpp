// One satellite against a catalog, second filter: the times when an object can be within the
// threshold D of the primary (issue 24). It plays the part of the time filter of Hoots,
// Crawford & Roehrich ("An analytic method to determine future close approaches between
// satellites", Celestial Mechanics 33, 1984), with distances evaluated by SGP4 instead of
// the node-crossing geometry, so that it holds for every orbit shape and under drag.
//
// Argument. Let V_p and V_j bound the speeds of the primary and of object j over the span.
// Then |d/dt (r_j - r_p)| <= V = V_p + V_j, so from one evaluation d(t) = |r_j(t) - r_p(t)|
// the distance stays above D on [t, t + (d(t) - D) / V): no approach within D can happen
// there. The filter steps through the span by these jumps. Where the jump is shorter than
// min_window_s, [t, t + W] becomes a window (W doubles on consecutive windows, up to
// max_window_s, so that a pair that stays close costs span / max_window_s evaluations).
// Every time outside the windows has d > D, so every closest approach with miss <= D lies
// strictly inside a window; the windows (merged when closer than max_window_s) go to the
// robust screener, which proves no miss inside them.
//
// Second bound from the same evaluation: with A_p + A_j bounding |r''| of the two and SGP4's
// velocities within eps of the positions' derivatives, the projection on the present
// direction gives d(t + h) >= d + (rdot - 2 eps) h - (A_p + A_j) h^2 / 2, rdot = the SGP4
// range rate, so d stays above D up to the positive root of that quadratic; the jump is the
// larger of the two. |r''| <= A = 1.01 mu / r_lo^2 + 1e-3 m/s^2: J2 adds at most 4.9e-3 of
// mu / r^2 and SGP4's other terms at most 3e-4 m/s^2 (sampled; the envelope's assumption
// S1, docs/VALIDATION.md); eps = velocity_allowance_mps (sgp4_motion.hpp), against what is measured.
//
// Speed bound (derived, with margin; checked, as the perturbation envelope is): vis-viva
// v^2 = mu (2/r - 1/a) with r >= r_lo, the proven (near-Earth) or sampled (deep space)
// radius bound of primary_prefilter.hpp over the span plus one orbit, and the osculating
// semi-major axis a <= a_cap = (r_lo + r_hi)/2 + 0.01 r_hi: the osculating a departs from the
// mean orbit's by the J2 short-period terms, 1.5 J2 (Re/a)^2 a ~ 1.6e-3 a, against the 1 %
// allowed. Checked at run time: every evaluation also gives SGP4's velocity (within 0.1 m/s
// of the position's derivative, sgp4_motion.hpp); an object whose SGP4 speed comes within
// kSpeedCheckMarginMps of its bound, whose SGP4 fails, or that has no radius bound is not
// filtered (its window is the whole span, and the screener reports what fails).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "evade/conjunction/sgp4_motion.hpp"
#include "evade/sgp4/sgp4.hpp"

namespace evade::conjunction {

/// A sampled SGP4 speed this close to the bound disables the filter for the object [m/s].
constexpr double kSpeedCheckMarginMps = 1.0;
// velocity_allowance_mps (SGP4's own velocity against d/dt of its position): sgp4_motion.hpp.

struct TimeFilterOptions {
  double threshold_m = 5000.0;  ///< D [m]
  double min_window_s = 1.0;    ///< the primary's track step: shorter jumps open a window [s]
  double max_window_s = 64.0;   ///< longest window step; windows closer than this merge [s]
};

/// [t0_s, t1_s] from the start of the screen [s].
struct TimeWindow {
  double t0_s = 0.0;
  double t1_s = 0.0;
};

/// One object of the catalog as the filter sees it: its propagator, the offset from its
/// element epoch to the start of the screen [s], and its motion's bounds (0: none).
struct FilterObject {
  const sgp4::Sgp4Propagator* prop = nullptr;
  double offset_s = 0.0;
  double speed_bound_mps = 0.0;  ///< of |d/dt r| [m/s]
  double accel_bound_mps2 = 0.0; ///< of |d2/dt2 r| [m/s^2]
};

/// What the filter found for one object against the primary.
struct ObjectWindows {
  std::vector<TimeWindow> windows;  ///< merged, increasing; empty: never within D
  bool unfiltered = false;          ///< the whole span (no bound, SGP4 error, speed check)
  std::string why_unfiltered;
  long evaluations = 0;             ///< SGP4 evaluations of the pair
};

/// The speed and acceleration bounds of an SGP4 object over [t0_s, t1_s] from its element
/// epoch (the interval is widened to at least 1.1 orbits; see above): prop and offset_s are
/// left empty; the bounds are 0 when the radius has no bound there.
FilterObject sgp4_motion_bounds(const sgp4::Sgp4Propagator& p, const sgp4::MeanElements& m,
                                double t0_s, double t1_s);

/// The primary's positions at t_k = k min_window_s (k < K) and t_K = span_s, computed once:
/// the filter's times are on this grid (a jump is rounded down to it).
struct PrimaryTrack {
  double step_s = 1.0;
  double span_s = 0.0;
  std::vector<Eigen::Vector3d> r_teme_m;  ///< K + 1 positions
  std::vector<Eigen::Vector3d> v_teme_mps;  ///< and SGP4's velocities
  double speed_bound_mps = 0.0;
  double accel_bound_mps2 = 0.0;
  std::string why_unusable;               ///< empty: usable (SGP4 and the speed check held)
  double time_s(long k) const;
  long last() const { return static_cast<long>(r_teme_m.size()) - 1; }
};

PrimaryTrack primary_track(const FilterObject& p, double span_s, const TimeFilterOptions& opt);

/// The windows of object j against the primary's track over [0, span_s] (see above).
ObjectWindows primary_time_windows(const PrimaryTrack& p, const FilterObject& j,
                                   const TimeFilterOptions& opt);

}  // namespace evade::conjunction
