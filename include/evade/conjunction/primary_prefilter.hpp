// One satellite against a catalog at the cost of the satellite: before anything is
// propagated, the objects that can never come within the threshold of the primary over the
// span are set aside by the perigee/apogee filter (the first of Hoots, Crawford & Roehrich,
// "An analytic method to determine future close approaches between satellites", Celestial
// Mechanics 33, 1984): |r_j - r_p| >= | |r_j| - |r_p| |, so an object whose radius range over
// the span lies entirely above the primary's largest radius + D, or entirely below its
// smallest - D, never comes within D. The radius ranges of near-Earth element sets are those
// of the SGP4 theory itself (sgp4::Sgp4Propagator::radius_bounds, proven from its formulas).
// Deep-space element sets (lunar-solar terms) are sampled: |r| every kPrefilterSampleS over
// the span, and between samples the scalar radius r(t) has |r''| <= |a| + v^2/r
// <= (mu/r^2)(1 + 1.5 J2 (Re/r)^2 + eps r^2/mu) + 2 mu/r^2 (vis-viva v^2 <= 2 mu / r, to the
// same J2/perturbation order) <= 3.1 mu / r^2 = B(r), so between samples h apart
// r(t) >= min sample - B h^2 / 8 (linear interpolation error of a function with |r''| <= B);
// B is evaluated at a lower bound of r valid over the whole span, found by fixed point from
// r >= Re (SGP4 reports decay below one Earth radius): R <- min sample - B(R) h^2 / 8 while it
// rises (each iterate is a valid bound given the previous one). The upper bound is the
// largest sample + B(R) h^2 / 8. The 3.1 (against 3 for a Keplerian orbit) covers J2 (1.6e-3
// at Re) and SGP4's perturbation (|p| <= 3e-4 m/s^2 sampled, docs/VALIDATION.md) with room;
// it rests on that envelope as the SGP4 screening theorem does (its assumption S1). An object
// whose SGP4 fails at a sample keeps no bound (kept), and every object is kept when the
// primary has no bound.
// The span is widened by kPrefilterPadS on each side (the screener's velocity and
// acceleration differences evaluate SGP4 up to 10 s outside it).
#pragma once

#include <vector>

#include "evade/sgp4/mean_elements.hpp"
#include "evade/sgp4/sgp4.hpp"

namespace evade::conjunction {

constexpr double kPrefilterPadS = 60.0;
/// Sample spacing of the deep-space radius bound [s] (a GEO object's bound is then within
/// ~300 km of its sampled range).
constexpr double kPrefilterSampleS = 1800.0;

/// What the filter did.
struct PrimaryPrefilterCounts {
  long objects = 0;         ///< element sets given (the primary included)
  long unbounded = 0;       ///< kept: no radius bound over the span (an SGP4 error)
  long sampled = 0;         ///< deep space: bound from samples (see above)
  long removed_radius = 0;  ///< set aside: radius ranges never within D of the primary's
  long removed_path = 0;    ///< set aside by the orbit-path filter (primary_path_filter.hpp)
  long path_tests = 0;      ///< pieces of the span the orbit-path filter tested
  long kept = 0;            ///< to be propagated and screened (the primary included)
  bool primary_bounded = false;
};

/// The sampled bound of |r| over t in [t0_s, t1_s] (seconds from the element epoch; see
/// above); bounded = false when SGP4 fails at a sample.
sgp4::RadiusBounds sampled_radius_bounds(const sgp4::Sgp4Propagator& p, double t0_s, double t1_s);

/// The primary (first element set with primary_norad) and the objects that may come within
/// threshold_m of it over [start, start + span_s] (start: UTC s since J2000), in catalog
/// order: those the perigee/apogee filter keeps, less those the orbit-path filter
/// (primary_path_filter.hpp; skipped when path_filter is false) sets aside. When no element set has primary_norad every element set is kept (the screen then
/// names the missing primary). The objects' bounds are computed on `threads` threads (>= 1).
std::vector<sgp4::MeanElements> prefilter_primary(const std::vector<sgp4::MeanElements>& all,
                                                  long primary_norad, double start_j2000_s,
                                                  double span_s, double threshold_m,
                                                  PrimaryPrefilterCounts* counts, int threads = 1,
                                                  bool path_filter = true);

}  // namespace evade::conjunction
