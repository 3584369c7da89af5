// The catalogs of issue 24's stress validation (sgp4_stress_validation_test.cpp), built to
// stress the screen and the perigee/apogee prefilter around a primary in a 700 km
// sun-synchronous orbit (sgp4_stress_catalog.cpp), and the radius range SGP4 gives an object.
#pragma once

#include <cstdint>
#include <vector>

#include "evade/sgp4/mean_elements.hpp"

namespace evade::conjunction::testing {

constexpr long kPrimary = 70000;
constexpr double kThresholdM = 5000.0;

// The extremes of |r| that SGP4 gives for m over [t0_s, t1_s] from the start (sampled every
// 15 s: at 7.5 km/s and near-circular orbits, |r| changes by < 1 m between samples near an
// extreme).
struct RadiusRange {
  double min_m = 1e12, max_m = 0.0;
};
RadiusRange sgp4_radius_range(const sgp4::MeanElements& m, double t0_s, double t1_s);

// The primary (NORAD kPrimary, first), its companions, HEO crossers and drifters, then
// sgp4_test_catalog's pairs and background up to total objects, seeded by seed.
std::vector<sgp4::MeanElements> stress_catalog(std::uint64_t seed, int total, double span_s);

}  // namespace evade::conjunction::testing
