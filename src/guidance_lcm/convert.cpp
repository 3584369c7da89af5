// LCM <-> guidance struct conversions (docs/GUIDANCE_NODE.md NODE-IF-2): field by field, bit-exact.
#include "evade/guidance_lcm/convert.hpp"

namespace evade::guidance_lcm {

void from_lcm(const evade_angles_t& m, guidance::AnglesMeasurement* out) noexcept {
  out->utime_us = m.utime;
  out->seq = m.seq;
  out->elevation_rad = m.elevation_rad;
  out->azimuth_rad = m.azimuth_rad;
  out->sigma_angle_rad = m.sigma_angle_rad;
  out->has_rates = m.has_rates;
  out->elevation_rate_radps = m.has_rates ? m.elevation_rate_radps : 0.0;
  out->azimuth_rate_radps = m.has_rates ? m.azimuth_rate_radps : 0.0;
  out->sigma_rate_radps = m.has_rates ? m.sigma_rate_radps : 0.0;
  out->has_range = m.has_range;
  out->range_m = m.has_range ? m.range_m : 0.0;
  out->range_rate_mps = m.has_range ? m.range_rate_mps : 0.0;
  out->valid = m.valid;
}

void from_lcm(const evade_nav_state_t& m, guidance::NavState* out) noexcept {
  out->utime_us = m.utime;
  for (int i = 0; i < 3; ++i) {
    out->r_eci_m[i] = m.r_eci_m[i];
    out->v_eci_mps[i] = m.v_eci_mps[i];
  }
  out->valid = m.valid;
}

void from_lcm(const evade_thrust_cmd_t& m, guidance::ThrustCommand* out) noexcept {
  out->utime_us = m.utime;
  out->mode = static_cast<guidance::GuidanceMode>(m.mode);
  for (int i = 0; i < 3; ++i) out->u_eci[i] = m.u_eci[i];
  out->accel_mps2 = m.accel_mps2;
  out->reason = static_cast<guidance::CommandReason>(m.reason);
}

void from_lcm(const evade_guidance_status_t& m, guidance::GuidanceStatus* out) noexcept {
  out->utime_us = m.utime;
  out->mode = static_cast<guidance::GuidanceMode>(m.mode);
  out->reason = static_cast<guidance::CommandReason>(m.reason);
  out->track_valid = m.track_valid;
  out->los_rate_radps = m.los_rate_radps;
  out->los_rate_var_rad2ps2 = m.los_rate_var_rad2ps2;
  for (int i = 0; i < 3; ++i) {
    out->e_theta_eci[i] = m.e_theta_eci[i];
    for (int j = 0; j < 3; ++j) out->e_theta_cov_eci(i, j) = m.e_theta_cov_eci[3 * i + j];
  }
  out->zem_valid = m.has_range;
  out->t_go_valid = m.has_range;
  out->zem_m = m.zem_m;
  out->t_go_s = m.t_go_s;
  out->dv_used_mps = m.dv_used_mps;
  out->cycles = static_cast<std::int64_t>(m.cycles);
}

void to_lcm(const guidance::AnglesMeasurement& a, std::int64_t seq, evade_angles_t* out) noexcept {
  out->utime = a.utime_us;
  out->seq = seq;
  out->valid = lcm_bool(a.valid);
  out->elevation_rad = a.elevation_rad;
  out->azimuth_rad = a.azimuth_rad;
  out->sigma_angle_rad = a.sigma_angle_rad;
  out->has_rates = lcm_bool(a.has_rates);
  out->elevation_rate_radps = a.elevation_rate_radps;
  out->azimuth_rate_radps = a.azimuth_rate_radps;
  out->sigma_rate_radps = a.sigma_rate_radps;
  out->has_range = lcm_bool(a.has_range);
  out->range_m = a.range_m;
  out->range_rate_mps = a.range_rate_mps;
  out->sigma_range_m = 0.0;         // not carried by AnglesMeasurement
  out->sigma_range_rate_mps = 0.0;
}

void to_lcm(const guidance::NavState& n, std::int64_t seq, evade_nav_state_t* out) noexcept {
  out->utime = n.utime_us;
  out->seq = seq;
  out->valid = lcm_bool(n.valid);
  for (int i = 0; i < 3; ++i) {
    out->r_eci_m[i] = n.r_eci_m[i];
    out->v_eci_mps[i] = n.v_eci_mps[i];
  }
}

void to_lcm(const guidance::ThrustCommand& c, std::int64_t seq, std::int64_t input_utime,
            evade_thrust_cmd_t* out) noexcept {
  out->utime = c.utime_us;
  out->seq = seq;
  out->mode = static_cast<std::int8_t>(c.mode);
  for (int i = 0; i < 3; ++i) out->u_eci[i] = c.u_eci[i];
  out->accel_mps2 = c.accel_mps2;
  out->reason = static_cast<std::int16_t>(c.reason);
  out->input_utime = input_utime;
}

void to_lcm(const guidance::GuidanceStatus& s, evade_guidance_status_t* out) noexcept {
  out->mode = static_cast<std::int8_t>(s.mode);
  out->reason = static_cast<std::int16_t>(s.reason);
  out->track_valid = lcm_bool(s.track_valid);
  out->los_rate_radps = s.los_rate_radps;
  out->los_rate_var_rad2ps2 = s.los_rate_var_rad2ps2;
  for (int i = 0; i < 3; ++i) {
    out->e_theta_eci[i] = s.e_theta_eci[i];
    for (int j = 0; j < 3; ++j) out->e_theta_cov_eci[3 * i + j] = s.e_theta_cov_eci(i, j);
  }
  out->has_range = lcm_bool(s.zem_valid && s.t_go_valid);
  out->zem_m = s.zem_valid ? s.zem_m : 0.0;
  out->t_go_s = s.t_go_valid ? s.t_go_s : 0.0;
  out->dv_used_mps = s.dv_used_mps;
}

void to_lcm(const guidance::PlanExecStatus& s, evade_guidance_status_t* out) noexcept {
  static_assert(static_cast<int>(guidance::PlanReject::kCount) == 12, "plan_n_rejected[12]");
  static_assert(BurnPlan::kMaxImpulses == 8, "plan_dv_delivered_mps[8]");
  out->plan_id = s.plan_id;
  out->plan_state = static_cast<std::int8_t>(s.state);
  out->plan_end = static_cast<std::int8_t>(s.end);
  out->plan_n_impulses = static_cast<std::int8_t>(s.n_impulses);
  out->plan_impulses_done = static_cast<std::int8_t>(s.impulses_done);
  for (int k = 0; k < BurnPlan::kMaxImpulses; ++k) {
    const auto i = static_cast<std::size_t>(k);
    out->plan_dv_delivered_mps[k] = s.dv_delivered_mps[i];
    out->plan_burn_start_utime[k] = s.burn_start_us[i];
    out->plan_burn_end_utime[k] = s.burn_end_us[i];
  }
  out->plan_dv_total_mps = s.dv_total_mps;
  out->plan_n_accepted = s.accepted;
  out->plan_last_reject = static_cast<std::int8_t>(s.last_reject);
  for (int r = 0; r < static_cast<int>(guidance::PlanReject::kCount); ++r)
    out->plan_n_rejected[r] = s.rejected[static_cast<std::size_t>(r)];
}

}  // namespace evade::guidance_lcm
