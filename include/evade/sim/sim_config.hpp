// Configuration of the close-range evasion simulator (paper 000, sec. 4 simulation).
//
// Truth: satellite and debris, each under two-body (+ J2) gravity in ECI (dynamics module),
// integrated together with DOP853; the satellite also gets the actuator's acceleration, held
// constant between command changes (zero-order hold). Times are seconds from the scenario
// epoch (t = 0 is the epoch of the scenario states).
#pragma once

#include <cstdint>
#include <string>

#include "evade/core/constants.hpp"
#include "evade/core/state.hpp"
#include "evade/dynamics/dop853.hpp"
#include "evade/dynamics/gravity.hpp"
#include "evade/guidance/guidance_law.hpp"

namespace evade::sim {

// Defaults are in the member initializers; unit, range and meaning of every field in
// sim_params.hpp (the one table every reader uses).

/// Angle sensor (satellite-centred ECI-parallel frame, paper 000 eq. 13–14). The default is
/// the ideal sensor: noise-free angles plus their true rates at 50 Hz, no latency.
struct SensorConfig {
  double rate_hz = 50.0;
  double noise_rad = 0.0;         ///< 1σ white noise on ε and on β·cos ε (tangent)
  double bias_rad = 0.0;          ///< constant bias added to ε and β
  double latency_s = 0.0;         ///< delay from time of validity to delivery
  double dropout_prob = 0.0;
  bool has_rates = true;          ///< rate-stabilised tracker: also ε̇, β̇
  double rate_noise_radps = 0.0;  ///< 1σ white noise on ε̇ and β̇ cos ε
  bool has_range = false;         ///< also range and range rate (radar)
  double range_noise_m = 0.0;
  double range_rate_noise_mps = 0.0;
  std::uint64_t seed = 1;         ///< std::mt19937_64 seed
};

/// Thruster: applies the command after latency_s, clipped to max_accel_mps2, with a random
/// direction error (angle ~ N(0, direction_error_rad²) about a random axis ⊥ the command).
struct ActuatorConfig {
  double max_accel_mps2 = 100.0;    ///< hardware limit
  double direction_error_rad = 0.0; ///< 1σ pointing error
  double latency_s = 0.0;           ///< command-to-thrust delay
  std::uint64_t seed = 2;
};

/// When the run starts and stops, relative to the nominal closest approach.
struct EncounterConfig {
  double search_s = 120.0;            ///< look for the nominal closest approach in [0, this]
  double detect_before_tca_s = 10.0;  ///< start the simulation this long before it
  double post_tca_s = 0.0;            ///< keep simulating this long after the closest approach
  double max_duration_s = 3600.0;     ///< give up (no closest approach) after this long
};

/// Real-time runs (`evade sim --lcm URL --realtime`, realtime_simulator.hpp): truth at
/// wall-clock pace; a step whose outputs leave later than this after its due time is late.
struct RealtimeConfig {
  double late_tolerance_s = 1e-3;  ///< lateness above which a step counts in sim_late_steps
  /// Loss-of-command timeout of the thruster drive: zero thrust once no new command has taken
  /// effect for this long (0: hold the last command indefinitely, the plain zero-order hold).
  double command_timeout_s = 0.0;
};

struct SimConfig {
  StateEci satellite0;  ///< at the epoch (t = 0)
  StateEci debris0;     ///< at the epoch (t = 0)
  GravityModel gravity = GravityModel::kTwoBodyJ2;
  EarthModel earth = kEarthDefault;
  EncounterConfig encounter;
  guidance::GuidanceConfig guidance;  ///< guidance.rate_hz is also the exchange rate
  SensorConfig sensor;
  ActuatorConfig actuator;
  RealtimeConfig realtime;
  AdaptiveOptions integrator = AdaptiveOptions::tight();

  /// Throws std::invalid_argument with the parameter tables' error text.
  void validate() const;
};

}  // namespace evade::sim
