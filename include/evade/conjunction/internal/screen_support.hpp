// Internal (not installed): what the robust screener's parts share
// (src/conjunction/robust_screen.cpp): the radius range and gravity bound of every object
// over the whole span, the reporting distance, the input checks, the order of the events and
// the sum of the statistics.
#pragma once

#include <vector>

#include "evade/conjunction/robust_screen.hpp"

namespace evade::conjunction::internal {

struct ObjectBounds {
  double r_min_m = 0.0;   // lower bound on |r| over the span
  double r_max_m = 0.0;   // upper bound on |r| over the span
  double g_max_mps2 = 0.0;  // upper bound on |r''|
};

// Largest reporting distance max_ij D_ij (D, or N times the largest possible R_c).
double max_reporting_distance_m(const std::vector<SpaceObject>& objects, const ScreenOptions& opt);

// Throws std::invalid_argument when the motion source does not hold one motion per object or
// the primary is not one of the objects.
void check_motion_and_primary(const std::vector<SpaceObject>& objects, const ScreenOptions& opt);

// Sorts events by tca_s, then i, then j.
void sort_events(std::vector<Conjunction>& ev);

// Keeps one event per closest approach (ev sorted by sort_events): two events of one pair
// whose misses agree within 1 cm and whose TCAs are within sqrt(2 m 1 cm) / v of each other
// (m the smaller miss, v the relative speed; at most 60 s) are one minimum of the distance,
// found twice where noise in the motion's velocity makes the range rate cross zero twice;
// the one with the smaller miss is kept. Returns how many were removed.
long merge_repeated_approaches(std::vector<Conjunction>& ev);

// Adds the per-step statistics of s (not pairs_after_apogee_perigee) to into.
void add_stats(ScreenStats& into, const ScreenStats& s);

}  // namespace evade::conjunction::internal
