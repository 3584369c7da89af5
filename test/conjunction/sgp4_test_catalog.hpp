// Seeded SGP4 element-set catalogs for the screening tests (issue 12): LEO background
// objects, slow co-orbital pairs (the same elements with the mean anomaly 0.005-0.04 deg
// apart and e, RAAN slightly different: relative speeds of a few m/s), near-tangent pairs
// (same plane node, inclinations 0.5-5 deg apart, both at the node within minutes of the
// start, so they pass each other at 60-650 m/s) and crossing pairs (the same with 20-90 deg).
// Element epochs are spread over the day before the start (the latest epoch).
#pragma once

#include <cmath>
#include <cstdint>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "evade/sgp4/catalog.hpp"
#include "evade/sgp4/mean_elements.hpp"
#include "evade/sgp4/tle_reader.hpp"

namespace evade::conjunction::testing {

struct Sgp4TestCatalogOptions {
  int background = 200;
  int coorbital_pairs = 4;
  int tangent_pairs = 8;
  int crossing_pairs = 8;
  std::uint64_t seed = 1;
};

inline std::vector<sgp4::MeanElements> sgp4_test_catalog(const Sgp4TestCatalogOptions& o) {
  std::mt19937_64 rng(o.seed);
  auto uni = [&rng](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  const double day0 = 318.5;  // 2026 day 318.5 is the start (latest epoch)
  long norad = 80000;
  auto base = [&](double epoch_day) {
    sgp4::MeanElements m;
    m.norad_id = norad++;
    m.name = "T" + std::to_string(m.norad_id);
    m.epoch_year = 2026;
    m.epoch_day_of_year = epoch_day;
    m.mean_motion_revpday = uni(13.2, 15.6);
    m.eccentricity = uni(0.0002, 0.012);
    m.inclination_deg = uni(20.0, 100.0);
    m.raan_deg = uni(0.0, 360.0);
    m.arg_perigee_deg = uni(0.0, 360.0);
    m.mean_anomaly_deg = uni(0.0, 360.0);
    m.bstar_per_er = uni(1e-6, 2e-4);
    return m;
  };
  std::vector<sgp4::MeanElements> out;
  out.push_back(base(day0));  // holds the latest epoch
  for (int k = 1; k < o.background; ++k) out.push_back(base(day0 - uni(0.0, 1.0)));
  for (int k = 0; k < o.coorbital_pairs; ++k) {
    sgp4::MeanElements a = base(day0 - uni(0.0, 0.5));
    a.name = "co" + std::to_string(k) + "a";
    sgp4::MeanElements b = a;
    b.norad_id = norad++;
    b.name = "co" + std::to_string(k) + "b";
    b.mean_anomaly_deg += (k % 2 ? -1.0 : 1.0) * uni(0.005, 0.04);
    b.eccentricity += uni(-1e-4, 1e-4);
    b.raan_deg += uni(-0.01, 0.01);
    out.push_back(a);
    out.push_back(b);
  }
  auto meeting_pair = [&](const std::string& tag, int k, double di_lo, double di_hi) {
    // Both at their ascending node (u = 0) about t_meet after the start: nearly circular
    // orbits of one mean motion, one node, inclinations di apart.
    sgp4::MeanElements a = base(day0);
    a.name = tag + std::to_string(k) + "a";
    a.eccentricity = uni(0.0002, 0.001);
    a.inclination_deg = uni(30.0, 80.0);
    const double t_meet_s = uni(0.0, 1800.0);
    const double deg_per_s = a.mean_motion_revpday * 360.0 / 86400.0;
    a.arg_perigee_deg = 0.0;
    a.mean_anomaly_deg = std::fmod(720.0 - deg_per_s * t_meet_s, 360.0);
    sgp4::MeanElements b = a;
    b.norad_id = norad++;
    b.name = tag + std::to_string(k) + "b";
    b.inclination_deg += (k % 2 ? -1.0 : 1.0) * uni(di_lo, di_hi);
    b.mean_anomaly_deg = std::fmod(a.mean_anomaly_deg + uni(-0.02, 0.02) + 360.0, 360.0);
    out.push_back(a);
    out.push_back(b);
  };
  for (int k = 0; k < o.tangent_pairs; ++k) meeting_pair("tg", k, 0.5, 5.0);
  for (int k = 0; k < o.crossing_pairs; ++k) meeting_pair("cx", k, 20.0, 90.0);
  return out;
}

#ifdef EVADE_SYNTHETIC_CATALOG
/// The shipped catalog scenarios/catalogs/synthetic-1200.tle (LEO, MEO, GEO, HEO; SGP4 and
/// SDP4), read as the CLI reads it (EVADE_SYNTHETIC_CATALOG: its path, from CMake).
inline sgp4::Catalog shipped_catalog() {
  std::ifstream in(EVADE_SYNTHETIC_CATALOG);
  std::ostringstream os;
  os << in.rdbuf();
  return sgp4::read_tle(os.str(), "synthetic-1200.tle");
}
#endif

}  // namespace evade::conjunction::testing
