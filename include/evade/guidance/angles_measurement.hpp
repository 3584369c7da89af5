// The angle measurement of the threat (paper 000 eq. 13–14: elevation ε and azimuth β of
// the LOS in the satellite-centred ECI-parallel frame), in the one shape it has between the
// node's edge and the LOS filter, and the one definition of "well formed" that the edge
// validator (guidance_lcm) and the guidance law both apply.
//
// The law keeps applying it although the node already did: flight software may link the law
// without the node, and a non-finite number must never reach the filter.
#pragma once

#include <cstdint>

namespace evade::guidance {

/// Allowed ranges of a measurement's fields (inclusive).
struct MeasurementLimits {
  static constexpr double kMaxElevationRad = 1.5707963267948966;  ///< π/2 (eq. 13)
  static constexpr double kMaxAbsAzimuthRad = 6.283185307179586;  ///< 2π (wrapped by the law)
  static constexpr double kMaxSigmaAngleRad = 0.5;  ///< a 30° 1σ is no measurement
  /// LOS rates reach V/r: 15 km/s at 1.5 cm is 1e6 rad/s, beyond any real encounter. The
  /// azimuth rate is bounded through β̇ cos ε (β̇ alone is unbounded at the pole).
  static constexpr double kMaxAngleRateRadps = 1.0e6;
  static constexpr double kMaxRangeM = 1.0e8;
  static constexpr double kMaxRangeRateMps = 1.0e5;
};

struct AnglesMeasurement {
  std::int64_t utime_us = 0;       ///< time of validity [µs]
  std::int64_t seq = 0;            ///< sensor sequence number
  double elevation_rad = 0.0;      ///< ε ∈ [-π/2, π/2]
  double azimuth_rad = 0.0;        ///< β ∈ [-2π, 2π] (wrapped internally)
  double sigma_angle_rad = 0.0;          ///< 1σ angle noise [rad], ≥ 0
  bool has_rates = false;          ///< the sensor also gives ε̇, β̇ (rate-stabilised tracker)
  double elevation_rate_radps = 0.0;
  double azimuth_rate_radps = 0.0;
  double sigma_rate_radps = 0.0;   ///< 1σ of the rates [rad/s], ≥ 0
  bool has_range = false;          ///< range and range rate present (e.g. radar)
  double range_m = 0.0;            ///< > 0
  double range_rate_mps = 0.0;     ///< ṙ, negative when closing
  bool valid = false;              ///< the sensor has a detection
};

/// Every numeric field finite (also those its flags mark unused: a sender that writes NaN
/// anywhere is broken) and every used field inside MeasurementLimits.
bool measurement_well_formed(const AnglesMeasurement& m) noexcept;

}  // namespace evade::guidance
