// The one reader of Keplerian elements and its limits (see read_elements.hpp).
#include "evade/config/read_elements.hpp"

#include <cmath>
#include <cstdlib>
#include <string>

#include "evade/core/param.hpp"

namespace evade::config {
namespace {

[[noreturn]] void fail(const Scenario& sc, const std::string& key, const std::string& value,
                       const std::string& allowed) {
  throw ConfigError(sc.source() + ": key '" + key + "' = '" + value +
                    "' is invalid: expected " + allowed);
}

// The value at key, checked against the limit; the missing-key and bad-value texts name the
// limit's interval (Scenario::get_double can only state a closed one).
double read_limited(const Scenario& sc, const std::string& key, const ElementLimit& limit) {
  const std::string allowed = "a number in " + element_interval_text(limit);
  if (!sc.has(key)) fail(sc, key, "<missing>", allowed + " (required key)");
  const std::string text = sc.get_string(key);  // the value as written; a list is refused here
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !element_value_ok(limit, v)) {
    fail(sc, key, text, allowed);
  }
  return sc.get_double(key, limit.lo, limit.hi);  // recorded as a number, as every typed read
}

}  // namespace

bool element_value_ok(const ElementLimit& limit, double v) noexcept {
  if (!std::isfinite(v)) return false;
  const bool above = limit.lo_open ? v > limit.lo : v >= limit.lo;
  const bool below = limit.hi_open ? v < limit.hi : v <= limit.hi;
  return above && below;
}

std::string element_interval_text(const ElementLimit& limit) {
  std::string s = limit.lo_open ? "(" : "[";
  s += param_value_text(limit.lo) + ", " + param_value_text(limit.hi);
  s += limit.hi_open ? ")" : "]";
  if (std::string(limit.unit) != "-") s += std::string(" ") + limit.unit;
  return s;
}

bool perigee_above_surface(double a_m, double e, const EarthModel& earth) noexcept {
  return a_m * (1.0 - e) > earth.re_m;
}

OrbitalElements read_elements(const Scenario& sc, const std::string& prefix,
                              const EarthModel& earth, OrbitPhase phase) {
  OrbitalElements oe;
  oe.a_m = read_limited(sc, prefix + "a_m", kSemiMajorAxisLimit);
  const bool circular_form = phase == OrbitPhase::kArgumentOfLatitude;
  oe.e = circular_form && !sc.has(prefix + "e")
             ? sc.get_double(prefix + "e", 0.0, 0.0, 0.0)  // absent: circular (recorded as 0)
             : read_limited(sc, prefix + "e", kEccentricityLimit);
  oe.i_rad = read_limited(sc, prefix + "i_deg", kInclinationLimit) * kDegToRad;
  oe.raan_rad = read_limited(sc, prefix + "raan_deg", kAngleLimit) * kDegToRad;
  if (circular_form) {
    oe.true_anomaly_rad = read_limited(sc, prefix + "arg_lat_deg", kAngleLimit) * kDegToRad;
  } else {
    oe.argp_rad = read_limited(sc, prefix + "argp_deg", kAngleLimit) * kDegToRad;
    const std::string anomaly =
        phase == OrbitPhase::kMeanAnomaly ? "mean_anomaly_deg" : "true_anomaly_deg";
    const double anomaly_rad = read_limited(sc, prefix + anomaly, kAngleLimit) * kDegToRad;
    oe.true_anomaly_rad = phase == OrbitPhase::kMeanAnomaly
                              ? true_from_mean_anomaly(anomaly_rad, oe.e)
                              : anomaly_rad;
  }
  if (!perigee_above_surface(oe.a_m, oe.e, earth)) {
    throw ConfigError(sc.source() + ": keys '" + prefix + "a_m' = '" + param_value_text(oe.a_m) +
                      "' and '" + prefix + "e' = '" + param_value_text(oe.e) +
                      "' are invalid: the perigee radius a (1 - e) = " +
                      param_value_text(oe.a_m * (1.0 - oe.e)) +
                      " m is inside the Earth (expected > re_m = " +
                      param_value_text(earth.re_m) + " m)");
  }
  return oe;
}

}  // namespace evade::config
