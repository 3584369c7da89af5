// Well-formedness of an angle measurement (include/evade/guidance/angles_measurement.hpp).
#include "evade/guidance/angles_measurement.hpp"

#include <cmath>

namespace evade::guidance {
namespace {

using L = MeasurementLimits;

bool all_finite(const AnglesMeasurement& m) noexcept {
  const double v[] = {m.elevation_rad,      m.azimuth_rad,       m.sigma_angle_rad,
                      m.elevation_rate_radps, m.azimuth_rate_radps, m.sigma_rate_radps,
                      m.range_m,            m.range_rate_mps};
  for (double x : v) {
    if (!std::isfinite(x)) return false;
  }
  return true;
}

bool angles_ok(const AnglesMeasurement& m) noexcept {
  return std::abs(m.elevation_rad) <= L::kMaxElevationRad &&
         std::abs(m.azimuth_rad) <= L::kMaxAbsAzimuthRad && m.sigma_angle_rad >= 0.0 &&
         m.sigma_angle_rad <= L::kMaxSigmaAngleRad;
}

bool rates_ok(const AnglesMeasurement& m) noexcept {
  if (!m.has_rates) return true;
  return std::abs(m.elevation_rate_radps) <= L::kMaxAngleRateRadps &&
         std::abs(m.azimuth_rate_radps * std::cos(m.elevation_rad)) <= L::kMaxAngleRateRadps &&
         m.sigma_rate_radps >= 0.0 && m.sigma_rate_radps <= L::kMaxAngleRateRadps;
}

bool range_ok(const AnglesMeasurement& m) noexcept {
  if (!m.has_range) return true;
  return m.range_m > 0.0 && m.range_m <= L::kMaxRangeM &&
         std::abs(m.range_rate_mps) <= L::kMaxRangeRateMps;
}

}  // namespace

bool measurement_well_formed(const AnglesMeasurement& m) noexcept {
  return all_finite(m) && angles_ok(m) && rates_ok(m) && range_ok(m);
}

}  // namespace evade::guidance
