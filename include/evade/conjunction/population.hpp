// Seeded synthetic LEO population for conjunction tests and benchmarks (issue 6).
//
// Distribution (all draws from std::mt19937_64 seeded by `seed`, so a seed is a catalog):
//  * background (fraction 1 - coorbital_fraction - crossing_fraction):
//      perigee altitude: mixture of shells 550 +/- 30 km (30 %), 780 +/- 40 km (25 %),
//      1000 +/- 60 km (15 %) and uniform 300..2000 km (30 %);
//      eccentricity: uniform 0..0.01, then apogee = perigee radius (1+e)/(1-e);
//      inclination: 53 deg (25 %), 86.4 deg (10 %), 97.5 +/- 1 deg (30 %), 51.6 deg (10 %),
//      uniform 0..180 deg (25 %); RAAN, argument of perigee, mean anomaly uniform 0..360 deg.
//  * slow co-orbital pairs (coorbital_fraction of the objects, two per pair): the second
//    object copies the first's elements with a = a1 + U(-300, 300) m, e + U(-2e-4, 2e-4)
//    (kept >= 0), i + U(-0.01, 0.01) deg, RAAN + U(-0.01, 0.01) deg and mean anomaly
//    shifted by U(-0.05, 0.05) deg (a few km along track): relative speeds of m/s, closest
//    approaches of 100 m to a few km, several per day.
//  * crossing pairs (crossing_fraction, two per pair): a meeting point on a sphere of radius
//    Re + U(400, 1200) km and a meeting time U(0, span) are drawn; two circular orbits
//    through the point with velocity directions U(20, 160) deg apart, the second object
//    displaced at the meeting time by U(0, 3000) m in a random direction; both are
//    propagated back (two-body) to t = 0. Their closest approach is near the meeting time,
//    with a km/s relative speed.
//  * near-tangent pairs (tangent_fraction, two per pair, default 0): as the crossing pairs
//    but with velocity directions U(0.5, 5) deg apart (relative speeds of 65..660 m/s, long
//    shallow encounters), named "tg<k>a/b", drawn after all the others.
//  * sizes: log-uniform 0.1..10 m; position errors: uniform 10..100 m.
#pragma once

#include <cstdint>
#include <vector>

#include "evade/conjunction/types.hpp"

namespace evade::conjunction {

struct PopulationOptions {
  std::size_t count = 1000;
  std::uint64_t seed = 1;
  double coorbital_fraction = 0.05;
  double crossing_fraction = 0.05;
  double tangent_fraction = 0.0;
  double span_s = 86400.0;  ///< meeting times of the crossing pairs are drawn in [0, span_s]
  EarthModel earth = kEarthDefault;
  /// Throws std::invalid_argument naming the option.
  void validate() const;
};

/// Objects with Cartesian states at t = 0 (names "bg<k>", "co<k>a/b", "cx<k>a/b").
std::vector<SpaceObject> synthetic_population(const PopulationOptions& opt);

}  // namespace evade::conjunction
