// Angle sensor model (paper 000 eq. 13–14 angles; see include/evade/sim/sensor_model.hpp).
#include "evade/sim/sensor_model.hpp"

#include <cmath>

#include "evade/guidance/los_geometry.hpp"

namespace evade::sim {

AngleSensor::AngleSensor(const SensorConfig& cfg) : cfg_(cfg), rng_(cfg.seed) {}

bool AngleSensor::measure(std::int64_t utime_us, const StateEci& satellite,
                          const StateEci& debris, guidance::AnglesMeasurement* out) {
  // Draw every random number in a fixed order whatever the options, so that changing one
  // option does not reshuffle the others' noise.
  const double u_drop = uniform_(rng_);
  const double n_el = normal_(rng_);
  const double n_az = normal_(rng_);
  const double n_elr = normal_(rng_);
  const double n_azr = normal_(rng_);
  const double n_r = normal_(rng_);
  const double n_rr = normal_(rng_);
  ++seq_;
  if (u_drop < cfg_.dropout_prob) return false;
  const Vec3 rel_r = debris.r_eci_m - satellite.r_eci_m;
  const Vec3 rel_v = debris.v_eci_mps - satellite.v_eci_mps;
  Vec3 u;
  Vec3 ud;
  guidance::los_from_relative(rel_r, rel_v, &u, &ud);
  const guidance::LosAngles a = guidance::los_angles_from_unit(u);
  const double ce = std::cos(a.elevation_rad);
  // Angle rates from u̇ = ε̇ y_s − β̇ cos ε z_s (eq. 16–18).
  const double cb = std::cos(a.azimuth_rad);
  const double sb = std::sin(a.azimuth_rad);
  const double se = std::sin(a.elevation_rad);
  const Vec3 y_s(-cb * se, -sb * se, ce);
  const Vec3 z_s(sb, -cb, 0.0);
  const double el_rate = ud.dot(y_s);
  const double az_rate_cos = -ud.dot(z_s);  // β̇ cos ε
  guidance::AnglesMeasurement m;
  m.utime_us = utime_us;
  m.seq = seq_;
  m.valid = true;
  m.elevation_rad = a.elevation_rad + cfg_.bias_rad + cfg_.noise_rad * n_el;
  // Noise on the tangent azimuth component; near the pole β is meaningless anyway.
  const double ce_safe = std::max(ce, 1e-9);
  m.azimuth_rad = a.azimuth_rad + cfg_.bias_rad + cfg_.noise_rad * n_az / ce_safe;
  if (m.elevation_rad > 0.5 * kPi) m.elevation_rad = kPi - m.elevation_rad;
  if (m.elevation_rad < -0.5 * kPi) m.elevation_rad = -kPi - m.elevation_rad;
  m.azimuth_rad = std::remainder(m.azimuth_rad, kTwoPi);
  m.sigma_angle_rad = cfg_.noise_rad;
  m.has_rates = cfg_.has_rates;
  if (cfg_.has_rates) {
    m.elevation_rate_radps = el_rate + cfg_.rate_noise_radps * n_elr;
    m.azimuth_rate_radps = (az_rate_cos + cfg_.rate_noise_radps * n_azr) / ce_safe;
    m.sigma_rate_radps = cfg_.rate_noise_radps;
  }
  m.has_range = cfg_.has_range;
  if (cfg_.has_range) {
    m.range_m = rel_r.norm() + cfg_.range_noise_m * n_r;
    m.range_rate_mps = u.dot(rel_v) + cfg_.range_rate_noise_mps * n_rr;
  }
  *out = m;
  return true;
}

}  // namespace evade::sim
