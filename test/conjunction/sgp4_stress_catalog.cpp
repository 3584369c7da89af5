// The stress catalogs of issue 24 (sgp4_stress_catalog.hpp): around a primary in a 700 km
// sun-synchronous orbit its own co-orbital companions, near-tangent and crossing meetings,
// HEO objects whose perigee lies below its altitude (radius ranges that overlap its own) and
// high-drag objects whose perigee starts just above its band and decays into it during the
// span; slow co-orbital, near-tangent and crossing pairs and the background from
// sgp4_test_catalog.hpp.
#include "sgp4_stress_catalog.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "evade/sgp4/sgp4.hpp"
#include "sgp4_test_catalog.hpp"

namespace evade::conjunction::testing {
namespace {

struct Stress {
  std::mt19937_64 rng;
  long norad = 70001;
  double uni(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
};

sgp4::MeanElements primary_elements() {
  sgp4::MeanElements p;
  p.norad_id = kPrimary;
  p.name = "PRIMARY";
  p.epoch_year = 2026;
  p.epoch_day_of_year = 318.5;  // the latest epoch of sgp4_test_catalog: the start
  p.mean_motion_revpday = 14.57;  // about 700 km
  p.eccentricity = 0.0012;
  p.inclination_deg = 98.2;
  p.raan_deg = 40.0;
  p.arg_perigee_deg = 90.0;
  p.mean_anomaly_deg = 10.0;
  p.bstar_per_er = 2e-5;
  return p;
}

sgp4::MeanElements renamed(sgp4::MeanElements m, Stress* s, const std::string& name) {
  m.norad_id = s->norad++;
  m.name = name;
  return m;
}

// The primary's companions: co-orbital (slow), and meetings at its ascending node within the
// span at near-tangent (0.5-5 deg) and crossing (20-80 deg) plane angles: the same elements
// but the inclination and the mean anomaly within 0.02 deg, so both cross the common node
// line within a fraction of a second of each other at every node passage, until their nodes,
// precessing at different rates under J2, part.
void primary_companions(const sgp4::MeanElements& p, Stress* s, std::vector<sgp4::MeanElements>* out) {
  for (int k = 0; k < 3; ++k) {
    sgp4::MeanElements c = renamed(p, s, "pco" + std::to_string(k));
    c.mean_anomaly_deg += (k % 2 ? -1.0 : 1.0) * s->uni(0.005, 0.04);
    c.eccentricity += s->uni(-1e-4, 1e-4);
    c.raan_deg += s->uni(-0.01, 0.01);
    out->push_back(c);
  }
  for (int k = 0; k < 8; ++k) {
    const bool tangent = k < 4;
    sgp4::MeanElements c = renamed(p, s, std::string(tangent ? "ptg" : "pcx") + std::to_string(k));
    c.inclination_deg += (k % 2 ? -1.0 : 1.0) * (tangent ? s->uni(0.5, 5.0) : s->uni(20.0, 80.0));
    // The primary passes its node every orbit; the companion reaches the node within 0.02 deg
    // of it on a pass chosen in the span (the mean anomaly shifted by whole orbits is the same).
    c.mean_anomaly_deg = std::fmod(p.mean_anomaly_deg + s->uni(-0.02, 0.02) + 360.0, 360.0);
    out->push_back(c);
  }
}

// HEO objects whose perigee (300-650 km) lies below the primary's altitude: their radius
// range contains the primary's at every instant, so the prefilter must keep them.
void heo_crossers(Stress* s, std::vector<sgp4::MeanElements>* out) {
  for (int k = 0; k < 6; ++k) {
    sgp4::MeanElements h = primary_elements();
    h = renamed(h, s, "heo" + std::to_string(k));
    h.epoch_day_of_year = 318.5 - s->uni(0.0, 1.0);
    const double rp_m = 6378135.0 + s->uni(300e3, 650e3), ra_m = s->uni(26e6, 46e6);
    const double a_m = 0.5 * (rp_m + ra_m);
    h.eccentricity = (ra_m - rp_m) / (ra_m + rp_m);
    h.mean_motion_revpday = std::sqrt(398600.8e9 / (a_m * a_m * a_m)) * 86400.0 / (2.0 * M_PI);
    h.inclination_deg = s->uni(50.0, 70.0);
    h.raan_deg = s->uni(0.0, 360.0);
    h.arg_perigee_deg = s->uni(0.0, 360.0);
    h.mean_anomaly_deg = s->uni(0.0, 360.0);
    h.bstar_per_er = s->uni(1e-5, 1e-4);
    out->push_back(h);
  }
}

}  // namespace

RadiusRange sgp4_radius_range(const sgp4::MeanElements& m, double t0_s, double t1_s) {
  const sgp4::Sgp4Propagator prop(m);
  const double offset_s = (318.5 - m.epoch_day_of_year) * 86400.0;
  RadiusRange r;
  for (double t = t0_s; t <= t1_s; t += 15.0) {
    const double x = prop.propagate_s(offset_s + t).r_teme_m.norm();
    r.min_m = std::min(r.min_m, x);
    r.max_m = std::max(r.max_m, x);
  }
  return r;
}

namespace {

// Near-circular, high-drag objects in the primary's plane (elsewhere on it) whose lowest
// radius over their first orbit is 0.15-0.6 km (1 day) or 1-4 km (7 days) above the primary's
// highest over the span + the threshold, and whose B* (0.08-0.15 1/ER, a high area-to-mass
// fragment at 720 km: the perigee sinks about 2.5 km a day under SGP4) takes them into the
// band before the end. Placed by SGP4's own radii (the short-period J2 terms move a 700 km
// orbit's radius by +-7 km about the mean elements' perigee and apogee): the mean motion is
// corrected until the first orbit's lowest radius is where it must be.
void drifters(const sgp4::MeanElements& p, double span_s, Stress* s,
              std::vector<sgp4::MeanElements>* out) {
  const double band_top_m = sgp4_radius_range(p, 0.0, span_s).max_m + kThresholdM;
  for (int k = 0; k < 4; ++k) {
    sgp4::MeanElements d = renamed(p, s, "drift" + std::to_string(k));
    d.eccentricity = s->uni(0.0003, 0.001);
    d.bstar_per_er = s->uni(0.08, 0.15);
    d.mean_anomaly_deg = s->uni(0.0, 360.0);
    d.arg_perigee_deg = s->uni(0.0, 360.0);
    const double target_m = band_top_m + s->uni(1e3, 4e3) * std::max(span_s / 604800.0, 0.15);
    double a_m = std::cbrt(398600.8e9 / std::pow(d.mean_motion_revpday * 2.0 * M_PI / 86400.0, 2));
    for (int it = 0; it < 4; ++it) {
      d.mean_motion_revpday = std::sqrt(398600.8e9 / (a_m * a_m * a_m)) * 86400.0 / (2.0 * M_PI);
      a_m += target_m - sgp4_radius_range(d, 0.0, 6000.0).min_m;
    }
    d.mean_motion_revpday = std::sqrt(398600.8e9 / (a_m * a_m * a_m)) * 86400.0 / (2.0 * M_PI);
    out->push_back(d);
  }
}

}  // namespace

std::vector<sgp4::MeanElements> stress_catalog(std::uint64_t seed, int total, double span_s) {
  Stress s{std::mt19937_64(seed * 7919 + 1)};
  const sgp4::MeanElements primary = primary_elements();  // a copy: out grows below
  std::vector<sgp4::MeanElements> out = {primary};
  primary_companions(primary, &s, &out);
  heo_crossers(&s, &out);
  drifters(primary, span_s, &s, &out);
  testing::Sgp4TestCatalogOptions o;
  o.seed = seed;
  o.coorbital_pairs = 6;
  o.tangent_pairs = 12;
  o.crossing_pairs = 12;
  o.background = total - static_cast<int>(out.size()) - 2 * (o.coorbital_pairs + o.tangent_pairs + o.crossing_pairs);
  for (const sgp4::MeanElements& m : testing::sgp4_test_catalog(o)) out.push_back(m);
  return out;
}

}  // namespace evade::conjunction::testing
