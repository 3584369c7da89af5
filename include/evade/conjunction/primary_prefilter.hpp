// One satellite against a catalog at the cost of the satellite: before anything is
// propagated, the objects that can never come within the threshold of the primary over the
// span are set aside by the perigee/apogee filter (the first of Hoots, Crawford & Roehrich,
// "An analytic method to determine future close approaches between satellites", Celestial
// Mechanics 33, 1984): |r_j - r_p| >= | |r_j| - |r_p| |, so an object whose radius range over
// the span lies entirely above the primary's largest radius + D, or entirely below its
// smallest - D, never comes within D. The radius ranges are those of the SGP4 theory itself
// (sgp4::Sgp4Propagator::radius_bounds, proven from its formulas, docs/VALIDATION.md); an
// object without one (deep space) is kept, and every object is kept when the primary has none.
// The span is widened by kPrefilterPadS on each side (the screener's velocity and
// acceleration differences evaluate SGP4 up to 10 s outside it).
#pragma once

#include <vector>

#include "evade/sgp4/mean_elements.hpp"

namespace evade::conjunction {

constexpr double kPrefilterPadS = 60.0;

/// What the filter did.
struct PrimaryPrefilterCounts {
  long objects = 0;         ///< element sets given (the primary included)
  long unbounded = 0;       ///< kept: no radius bound over the span (deep space, decay)
  long removed_radius = 0;  ///< set aside: radius ranges never within D of the primary's
  long kept = 0;            ///< to be propagated and screened (the primary included)
  bool primary_bounded = false;
};

/// The primary (first element set with primary_norad) and the objects that may come within
/// threshold_m of it over [start, start + span_s] (start: UTC s since J2000), in catalog
/// order. When no element set has primary_norad every element set is kept (the screen then
/// names the missing primary).
std::vector<sgp4::MeanElements> prefilter_primary(const std::vector<sgp4::MeanElements>& all,
                                                  long primary_norad, double start_j2000_s,
                                                  double span_s, double threshold_m,
                                                  PrimaryPrefilterCounts* counts);

}  // namespace evade::conjunction
