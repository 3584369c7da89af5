// GuidanceConfig parameter table (include/evade/guidance/guidance_params.hpp). Paper 000
// (Yao & Wang 2012) fixes the law; these are the limits and filter tunings around it.
#include "evade/guidance/guidance_params.hpp"

namespace evade::guidance {
namespace {

using C = GuidanceConfig;

const Param<C> kRows[] = {
    with_flag(EVADE_PARAM_REAL(C, max_accel_mps2, "m/s^2", 0.0, 100.0, true,
                               "thrust acceleration commanded in EVADE (paper 000: 0.2-10 m/s^2)"),
              "--max-accel-mps2", "--accel-mps2,--accel"),
    EVADE_PARAM_REAL(C, dv_budget_mps, "m/s", 0.0, 1e4, true,
                     "delta-v the law may spend on one encounter"),
    EVADE_PARAM_REAL(C, max_burn_s, "s", 0.0, 1e5, true, "burn time the law may spend"),
    with_flag(EVADE_PARAM_REAL(C, stale_limit_s, "s", 0.0, 60.0, true,
                               "age beyond which nav or a measurement is stale (edge, law and watchdog)"),
              "--stale-limit-s"),
    with_flag(EVADE_PARAM_REAL(C, rate_hz, "Hz", 0.0, 1000.0, true,
                               "guidance cycle rate: the node's loop, the simulator's exchange rate"),
              "--guidance-rate-hz", "--rate-hz,--guidance-hz"),
    EVADE_PARAM_REAL(C, rate_noise_threshold_radps, "rad/s", 0.0, 1.0, false,
                     "LOS rate at or below which e_theta falls back to the zenith convention"),
    EVADE_PARAM_REAL(C, rate_noise_k_sigma, "-", 0.0, 100.0, false,
                     "also fall back while the LOS rate is within k sigma of zero"),
    EVADE_PARAM_REAL(C, zem_trigger_m, "m", 0.0, 1e8, true,
                     "with range known, evade only when the zero-effort miss is below this"),
    EVADE_PARAM_INT(C, min_track_updates, "-", 1, 1000,
                    "accepted measurements before a track counts as established"),
    EVADE_PARAM_BOOL(C, armed, "start armed (the operator's evade_arm_t changes it in flight)"),
    EVADE_PARAM_REAL(C, filter.process_noise_radps2, "rad/s^2/sqrt(Hz)", 0.0, 1e3, true,
                     "square root of the LOS-acceleration noise density of the LOS filter"),
    EVADE_PARAM_REAL(C, filter.init_rate_sigma_radps, "rad/s", 0.0, 10.0, true,
                     "initial 1-sigma of each tangent LOS-rate component"),
    EVADE_PARAM_REAL(C, filter.angle_sigma_floor_rad, "rad", 0.0, 1.0, true,
                     "lower bound on a measurement's angle sigma"),
    EVADE_PARAM_REAL(C, filter.rate_sigma_floor_radps, "rad/s", 0.0, 1.0, true,
                     "lower bound on a measurement's rate sigma"),
    EVADE_PARAM_REAL(C, filter.gate_chi2_2dof, "-", 0.0, 1e6, true,
                     "innovation gate, angles only (chi-square 2 dof; 13.82 is p = 0.999)"),
    EVADE_PARAM_REAL(C, filter.gate_chi2_4dof, "-", 0.0, 1e6, true,
                     "innovation gate, angles and rates (chi-square 4 dof; 18.47 is p = 0.999)"),
    EVADE_PARAM_REAL(C, filter.reinit_gap_s, "s", 0.0, 3600.0, true,
                     "re-initialise the track after this long without an accepted update"),
    EVADE_PARAM_INT(C, filter.max_consecutive_rejects, "-", 1, 100000,
                    "re-initialise the track after this many gated measurements in a row"),
};

}  // namespace

ParamTable<GuidanceConfig> guidance_params() noexcept { return make_param_table(kRows); }

}  // namespace evade::guidance
