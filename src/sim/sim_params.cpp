// SimConfig parameter table (include/evade/sim/sim_params.hpp): the paper 000 simulation
// (Yao & Wang 2012, sec. 4) and the sensor and actuator models around it.
#include "evade/sim/sim_params.hpp"

namespace evade::sim {
namespace {

using C = SimConfig;

const Param<C> kRows[] = {
    EVADE_PARAM_REAL(C, encounter.search_s, "s", 1e-3, 1e6, false,
                     "look for the nominal closest approach within this time of the epoch"),
    with_flag(EVADE_PARAM_REAL(C, encounter.detect_before_tca_s, "s", 1e-3, 1e5, false,
                               "detection: the run starts this long before the nominal closest approach"),
              "--detect-s", "--detect"),
    EVADE_PARAM_REAL(C, encounter.post_tca_s, "s", 0.0, 1e4, false,
                     "keep simulating this long after the closest approach"),
    EVADE_PARAM_REAL(C, encounter.max_duration_s, "s", 1e-3, 1e6, false,
                     "give up when no closest approach occurs within this run time"),
    with_flag(EVADE_PARAM_REAL(C, sensor.rate_hz, "Hz", 1e-3, 1000.0, false, "angle sensor sample rate"),
              "--sensor-rate-hz"),
    with_flag(EVADE_PARAM_REAL(C, sensor.noise_rad, "rad", 0.0, 1.0, false,
                               "1-sigma white noise on elevation and on azimuth times cos(elevation)"),
              "--noise-rad"),
    EVADE_PARAM_REAL(C, sensor.bias_rad, "rad", -1.0, 1.0, false,
                     "constant bias added to both angles"),
    EVADE_PARAM_REAL(C, sensor.latency_s, "s", 0.0, 10.0, false,
                     "delay from a sample's time of validity to its delivery"),
    EVADE_PARAM_REAL(C, sensor.dropout_prob, "-", 0.0, 0.999, false,
                     "probability that a sample is lost"),
    EVADE_PARAM_BOOL(C, sensor.has_rates, "the sensor also measures the angle rates"),
    with_flag(EVADE_PARAM_REAL(C, sensor.rate_noise_radps, "rad/s", 0.0, 1.0, false,
                               "1-sigma white noise on the measured angle rates"),
              "--rate-noise-radps"),
    EVADE_PARAM_BOOL(C, sensor.has_range, "the sensor also measures range and range rate"),
    EVADE_PARAM_REAL(C, sensor.range_noise_m, "m", 0.0, 1e6, false, "1-sigma range noise"),
    EVADE_PARAM_REAL(C, sensor.range_rate_noise_mps, "m/s", 0.0, 1e4, false,
                     "1-sigma range-rate noise"),
    EVADE_PARAM_SEED(C, sensor.seed, "seed of the sensor's random numbers"),
    EVADE_PARAM_REAL(C, actuator.max_accel_mps2, "m/s^2", 1e-6, 1000.0, false,
                     "thruster hardware limit (the command is clipped to it)"),
    EVADE_PARAM_REAL(C, actuator.direction_error_rad, "rad", 0.0, 3.14159, false,
                     "1-sigma thrust pointing error about a random axis"),
    EVADE_PARAM_REAL(C, actuator.latency_s, "s", 0.0, 10.0, false,
                     "delay from a command to its thrust"),
    EVADE_PARAM_SEED(C, actuator.seed, "seed of the actuator's random numbers"),
    EVADE_PARAM_REAL(C, realtime.late_tolerance_s, "s", 1e-6, 1.0, false,
                     "real-time runs: a step processed later than this after its wall-clock "
                     "time counts as late (sim_late_steps)"),
    EVADE_PARAM_REAL(C, realtime.command_timeout_s, "s", 0.0, 3600.0, false,
                     "real-time runs: the thruster drive's loss-of-command timeout, zero thrust "
                     "once no new command has taken effect for this long (0: hold the last "
                     "command indefinitely)"),
    EVADE_PARAM_REAL(C, integrator.rel_tol, "-", 1e-15, 1e-3, false,
                     "relative tolerance of the truth integrator (DOP853)"),
    EVADE_PARAM_REAL(C, integrator.abs_tol, "m", 1e-15, 1.0, false,
                     "absolute tolerance of the truth integrator (m and m/s)"),
};

}  // namespace

ParamTable<SimConfig> sim_params() noexcept { return make_param_table(kRows); }

}  // namespace evade::sim
