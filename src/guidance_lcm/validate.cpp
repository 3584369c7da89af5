// Edge validation of LCM messages (design_node.md NODE-IN-2). Angles follow paper 000
// eq. 13-14: elevation in [-pi/2, pi/2], azimuth in [-2pi, 2pi] (the law wraps it). A message
// flagged valid = 0 is well formed ("no detection", "nav invalid"): it passes and the law
// decides what it means.
#include "evade/guidance_lcm/validate.hpp"

#include <cmath>

namespace evade::guidance_lcm {
namespace {

bool finite(double x) noexcept { return std::isfinite(x); }
bool finite3(const double* v) noexcept { return finite(v[0]) && finite(v[1]) && finite(v[2]); }
bool within(double x, double lo, double hi) noexcept { return x >= lo && x <= hi; }
bool norm_le(const double* v, double max) noexcept {
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) <= max;
}

}  // namespace

Reason validate(const evade_angles_t& m) noexcept {
  if (!finite(m.elevation_rad) || !finite(m.azimuth_rad) || !finite(m.sigma_angle_rad))
    return Reason::kNotFinite;
  if (m.has_rates && (!finite(m.elevation_rate_radps) || !finite(m.azimuth_rate_radps) ||
                      !finite(m.sigma_rate_radps)))
    return Reason::kNotFinite;
  if (m.has_range && (!finite(m.range_m) || !finite(m.range_rate_mps) ||
                      !finite(m.sigma_range_m) || !finite(m.sigma_range_rate_mps)))
    return Reason::kNotFinite;
  if (!within(m.elevation_rad, -Limits::kMaxElevationRad, Limits::kMaxElevationRad) ||
      !within(m.azimuth_rad, Limits::kMinAzimuthRad, Limits::kMaxAzimuthRad) ||
      !(m.sigma_angle_rad >= 0.0 && m.sigma_angle_rad <= Limits::kMaxSigmaAngleRad))
    return Reason::kOutOfRange;
  if (m.has_rates &&
      (!within(m.elevation_rate_radps, -Limits::kMaxAngleRateRadps, Limits::kMaxAngleRateRadps) ||
       !within(m.azimuth_rate_radps * std::cos(m.elevation_rad), -Limits::kMaxAngleRateRadps,
               Limits::kMaxAngleRateRadps) ||
       !(m.sigma_rate_radps >= 0.0 && m.sigma_rate_radps <= Limits::kMaxAngleRateRadps)))
    return Reason::kOutOfRange;
  if (m.has_range &&
      (!(m.range_m > 0.0 && m.range_m <= Limits::kMaxRangeM) ||
       !within(m.range_rate_mps, -Limits::kMaxRangeRateMps, Limits::kMaxRangeRateMps) ||
       !(m.sigma_range_m >= 0.0) || !(m.sigma_range_rate_mps >= 0.0)))
    return Reason::kOutOfRange;
  return Reason::kOk;
}

Reason validate(const evade_nav_state_t& m) noexcept {
  if (!finite3(m.r_eci_m) || !finite3(m.v_eci_mps)) return Reason::kNotFinite;
  if (!norm_le(m.r_eci_m, Limits::kMaxPositionM) || !norm_le(m.v_eci_mps, Limits::kMaxVelocityMps))
    return Reason::kOutOfRange;
  return Reason::kOk;
}

Reason validate(const evade_arm_t&) noexcept { return Reason::kOk; }

Reason validate(const evade_sim_clock_t& m) noexcept {
  return m.utime >= 0 ? Reason::kOk : Reason::kOutOfRange;
}

Reason validate(const evade_thrust_cmd_t& m) noexcept {
  if (!finite3(m.u_eci) || !finite(m.accel_mps2)) return Reason::kNotFinite;
  if (m.mode < evade_thrust_cmd_t::MODE_STANDBY || m.mode > evade_thrust_cmd_t::MODE_SAFE)
    return Reason::kOutOfRange;
  if (!(m.accel_mps2 >= 0.0 && m.accel_mps2 <= Limits::kMaxAccelMps2)) return Reason::kOutOfRange;
  const double n = std::sqrt(m.u_eci[0] * m.u_eci[0] + m.u_eci[1] * m.u_eci[1] +
                             m.u_eci[2] * m.u_eci[2]);
  if (m.accel_mps2 > 0.0 && std::fabs(n - 1.0) > Limits::kUnitTolerance)
    return Reason::kOutOfRange;
  if (m.accel_mps2 == 0.0 && n != 0.0 && std::fabs(n - 1.0) > Limits::kUnitTolerance)
    return Reason::kOutOfRange;
  return Reason::kOk;
}

const char* reason_name(Reason r) noexcept {
  switch (r) {
    case Reason::kOk: return "ok";
    case Reason::kDecodeFailed: return "decode_failed";
    case Reason::kOversize: return "oversize";
    case Reason::kNotFinite: return "not_finite";
    case Reason::kOutOfRange: return "out_of_range";
    case Reason::kFromFuture: return "from_future";
    case Reason::kStaleUtime: return "stale_utime";
    case Reason::kDuplicateSeq: return "duplicate_seq";
    case Reason::kOutOfOrderSeq: return "out_of_order_seq";
    case Reason::kCount: break;
  }
  return "?";
}

}  // namespace evade::guidance_lcm
