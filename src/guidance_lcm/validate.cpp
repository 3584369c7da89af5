// Edge validation of LCM messages (GUIDANCE_NODE.md NODE-IN-2). Angles follow paper 000
// eq. 13-14 through guidance::measurement_well_formed (the law's own definition). A message
// flagged valid = 0 is well formed ("no detection", "nav invalid"): it passes and the law
// decides what it means.
#include "evade/guidance_lcm/validate.hpp"

#include <cmath>
#include <cstddef>

#include "evade/guidance/angles_measurement.hpp"
#include "evade/guidance_lcm/convert.hpp"

namespace evade::guidance_lcm {
namespace {

bool finite(double x) noexcept { return std::isfinite(x); }
bool finite3(const double* v) noexcept { return finite(v[0]) && finite(v[1]) && finite(v[2]); }
bool norm_le(const double* v, double max) noexcept {
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) <= max;
}

}  // namespace

// Every numeric field finite (also those the flags mark unused: a sender that writes NaN
// anywhere is broken), then the law's own definition of a well-formed measurement.
Reason validate(const evade_angles_t& m) noexcept {
  const double fields[] = {m.elevation_rad,        m.azimuth_rad,       m.sigma_angle_rad,
                           m.elevation_rate_radps, m.azimuth_rate_radps, m.sigma_rate_radps,
                           m.range_m,              m.range_rate_mps,    m.sigma_range_m,
                           m.sigma_range_rate_mps};
  for (double x : fields) {
    if (!finite(x)) return Reason::kNotFinite;
  }
  guidance::AnglesMeasurement a;
  from_lcm(m, &a);
  if (!guidance::measurement_well_formed(a)) return Reason::kOutOfRange;
  if (m.has_range && !(m.sigma_range_m >= 0.0 && m.sigma_range_rate_mps >= 0.0))
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

Reason validate(const evade_key_cmd_t& m) noexcept {
  const bool op_ok = m.op == evade_key_cmd_t::OP_ACTIVATE || m.op == evade_key_cmd_t::OP_RETIRE;
  return op_ok && m.key_id > 0 ? Reason::kOk : Reason::kOutOfRange;
}

Reason validate(const evade_sim_clock_t& m) noexcept {
  return m.utime >= 0 && m.utime <= Limits::kMaxTickUtimeUs ? Reason::kOk : Reason::kOutOfRange;
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

namespace {

// Names in the order of the enumerators of Reason (input_accounting.hpp); the static_assert
// below keeps the two the same length.
constexpr const char* kReasonNames[] = {
    "ok",           "decode_failed",   "oversize",       "not_finite",
    "out_of_range", "from_future",     "stale_utime",    "duplicate_seq",
    "out_of_order_seq", "seq_jump",    "unsigned",       "unknown_key",
    "bad_mac",      "standby_key",     "retired_key",    "wrong_key_role",
    "too_short_for_trailer", "replayed_arsn", "verify_budget", "not_persisted",
    "queue_full",   "inbox_full",      "stopped",        "table_full",
    "not_applicable"};
static_assert(sizeof(kReasonNames) / sizeof(kReasonNames[0]) ==
                  static_cast<std::size_t>(Reason::kCount),
              "one name per Reason");

}  // namespace

const char* reason_name(Reason r) noexcept {
  const auto i = static_cast<std::size_t>(r);
  return i < static_cast<std::size_t>(Reason::kCount) ? kReasonNames[i] : "?";
}

}  // namespace evade::guidance_lcm
