// Real-time closed-loop simulation (`evade sim --lcm URL --realtime`, docs/VALIDATION.md
// "Real-time HIL"): the same truth, sensor and actuator models as run_simulation, but truth
// advances at wall-clock pace on a RealtimeLink and the guidance runs on its own clock. The
// sensor publishes each sample stamped with its time of validity, when it is delivered
// (validity + sensor.latency_s); navigation is published at every sample time; the actuator
// applies the newest command it has received (zero-order hold) actuator.latency_s after its
// receipt and records the command's age (apply time − the command's utime). When the
// simulator cannot keep up, it never slows time: the step is processed late, counted
// (late_steps, beyond realtime.late_tolerance_s), and the run goes on. With
// realtime.command_timeout_s > 0 the thruster drive cuts the thrust when no new command has
// taken effect for that long (a lost link must not leave the thruster firing).
#pragma once

#include "evade/sim/realtime_link.hpp"
#include "evade/sim/simulator.hpp"

namespace evade::sim {

struct RealtimeResult {
  SimResult sim;                  ///< sim.cycles = commands applied
  long commands_received = 0;     ///< by the link, including replaced ones
  long commands_discarded_old = 0;        ///< not newer than one received before (never applied)
  long commands_discarded_malformed = 0;  ///< failed decoding or validation (never applied)
  long commands_applied = 0;      ///< taken by the actuator (newest at each wake-up)
  long command_timeouts = 0;      ///< thrust cut by realtime.command_timeout_s (no new command)
  double command_age_ms_p50 = 0.0;  ///< apply time − command utime, over applied commands
  double command_age_ms_p99 = 0.0;
  double command_age_ms_max = 0.0;
  long steps = 0;                 ///< event steps processed
  long late_steps = 0;            ///< steps processed later than realtime.late_tolerance_s
  double late_max_ms = 0.0;       ///< largest lateness of any step
  std::int64_t start_utime_us = 0;  ///< wall clock of the run's first instant
};

/// Runs one real-time simulation against link. Throws std::invalid_argument for a bad
/// config and std::runtime_error if the integration fails (link errors propagate).
RealtimeResult run_realtime_simulation(const SimConfig& cfg, RealtimeLink& link,
                                       const SampleCallback& on_sample = {});

}  // namespace evade::sim
