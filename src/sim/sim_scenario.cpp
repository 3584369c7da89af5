// Scenario → SimConfig (keys and ranges listed here; defaults are the ideal sensor/actuator).
#include "evade/sim/sim_scenario.hpp"

#include <cmath>

#include "evade/core/epoch.hpp"

namespace evade::sim {

SimConfig sim_config_from_scenario(const config::Scenario& sc) {
  SimConfig c;
  constexpr double kR = 1e8;  // |r| bound [m]
  constexpr double kV = 1e5;  // |v| bound [m/s]
  if (sc.has("epoch_utc")) {
    const std::string e = sc.get_string("epoch_utc");
    try {
      (void)parse_calendar_utc(e);
    } catch (const std::exception& ex) {
      throw config::ConfigError("epoch_utc = '" + e + "': " + ex.what());
    }
  }
  if (sc.has("description")) sc.mark_used("description");
  c.satellite0.r_eci_m = sc.get_vec3("satellite.r_eci_m", -kR, kR);
  c.satellite0.v_eci_mps = sc.get_vec3("satellite.v_eci_mps", -kV, kV);
  c.debris0.r_eci_m = sc.get_vec3("debris.r_eci_m", -kR, kR);
  c.debris0.v_eci_mps = sc.get_vec3("debris.v_eci_mps", -kV, kV);
  const std::string g = sc.get_enum("gravity", {"two_body", "two_body_j2"}, "two_body_j2");
  c.gravity = (g == "two_body") ? GravityModel::kTwoBody : GravityModel::kTwoBodyJ2;
  c.encounter_search_s = sc.get_double("encounter.search_s", 1e-3, 1e6, c.encounter_search_s);
  c.detect_before_tca_s =
      sc.get_double("encounter.detect_before_tca_s", 1e-3, 1e5, c.detect_before_tca_s);
  c.post_tca_s = sc.get_double("encounter.post_tca_s", 0.0, 1e4, c.post_tca_s);
  c.max_duration_s = sc.get_double("encounter.max_duration_s", 1e-3, 1e6, c.max_duration_s);

  c.armed = sc.get_bool("guidance.armed", true);
  c.guidance_rate_hz = sc.get_double("guidance.rate_hz", 1e-3, 1000.0, c.guidance_rate_hz);
  guidance::GuidanceConfig& gc = c.guidance;
  gc.nominal_cycle_s = 1.0 / c.guidance_rate_hz;
  gc.max_accel_mps2 = sc.get_double("guidance.max_accel_mps2", 1e-6, 100.0, gc.max_accel_mps2);
  gc.dv_budget_mps = sc.get_double("guidance.dv_budget_mps", 1e-6, 1e4, gc.dv_budget_mps);
  gc.max_burn_s = sc.get_double("guidance.max_burn_s", 1e-6, 1e5, gc.max_burn_s);
  gc.stale_limit_s = sc.get_double("guidance.stale_limit_s", 1e-6, 60.0, gc.stale_limit_s);
  gc.rate_noise_threshold_radps = sc.get_double("guidance.rate_noise_threshold_radps", 0.0,
                                                1.0, gc.rate_noise_threshold_radps);
  gc.rate_noise_k_sigma =
      sc.get_double("guidance.rate_noise_k_sigma", 0.0, 100.0, gc.rate_noise_k_sigma);
  gc.zem_trigger_m = sc.get_double("guidance.zem_trigger_m", 1e-6, 1e8, gc.zem_trigger_m);
  gc.min_track_updates =
      static_cast<int>(sc.get_int("guidance.min_track_updates", 1, 1000, gc.min_track_updates));
  guidance::LosFilterConfig& fc = gc.filter;
  fc.process_noise_radps2 =
      sc.get_double("guidance.filter.process_noise_radps2", 1e-15, 1e3, fc.process_noise_radps2);
  fc.init_rate_sigma_radps = sc.get_double("guidance.filter.init_rate_sigma_radps", 1e-15, 10.0,
                                           fc.init_rate_sigma_radps);
  fc.angle_sigma_floor_rad = sc.get_double("guidance.filter.angle_sigma_floor_rad", 1e-15, 1.0,
                                           fc.angle_sigma_floor_rad);
  fc.rate_sigma_floor_radps = sc.get_double("guidance.filter.rate_sigma_floor_radps", 1e-15,
                                            1.0, fc.rate_sigma_floor_radps);
  fc.gate_chi2_2dof = sc.get_double("guidance.filter.gate_chi2_2dof", 1e-3, 1e6, fc.gate_chi2_2dof);
  fc.gate_chi2_4dof = sc.get_double("guidance.filter.gate_chi2_4dof", 1e-3, 1e6, fc.gate_chi2_4dof);
  fc.reinit_gap_s = sc.get_double("guidance.filter.reinit_gap_s", 1e-6, 3600.0, fc.reinit_gap_s);
  fc.max_consecutive_rejects = static_cast<int>(sc.get_int(
      "guidance.filter.max_consecutive_rejects", 1, 100000, fc.max_consecutive_rejects));

  SensorConfig& s = c.sensor;
  s.rate_hz = sc.get_double("sensor.rate_hz", 1e-3, 1000.0, s.rate_hz);
  s.noise_rad = sc.get_double("sensor.noise_rad", 0.0, 1.0, s.noise_rad);
  s.bias_rad = sc.get_double("sensor.bias_rad", -1.0, 1.0, s.bias_rad);
  s.latency_s = sc.get_double("sensor.latency_s", 0.0, 10.0, s.latency_s);
  s.dropout_prob = sc.get_double("sensor.dropout_prob", 0.0, 0.999, s.dropout_prob);
  s.provide_rates = sc.get_bool("sensor.rates", s.provide_rates);
  s.rate_noise_radps = sc.get_double("sensor.rate_noise_radps", 0.0, 1.0, s.rate_noise_radps);
  s.provide_range = sc.get_bool("sensor.range", s.provide_range);
  s.range_noise_m = sc.get_double("sensor.range_noise_m", 0.0, 1e6, s.range_noise_m);
  s.range_rate_noise_mps =
      sc.get_double("sensor.range_rate_noise_mps", 0.0, 1e4, s.range_rate_noise_mps);
  s.seed = static_cast<std::uint64_t>(sc.get_int("sensor.seed", 0, 1L << 62, 1));

  ActuatorConfig& a = c.actuator;
  a.max_accel_mps2 = sc.get_double("actuator.max_accel_mps2", 1e-6, 1000.0, a.max_accel_mps2);
  a.direction_error_rad =
      sc.get_double("actuator.direction_error_rad", 0.0, 3.14159, a.direction_error_rad);
  a.latency_s = sc.get_double("actuator.latency_s", 0.0, 10.0, a.latency_s);
  a.seed = static_cast<std::uint64_t>(sc.get_int("actuator.seed", 0, 1L << 62, 2));

  c.integrator.rel_tol = sc.get_double("integrator.rel_tol", 1e-15, 1e-3, c.integrator.rel_tol);
  c.integrator.abs_tol = sc.get_double("integrator.abs_tol", 1e-15, 1.0, c.integrator.abs_tol);
  return c;
}

}  // namespace evade::sim
