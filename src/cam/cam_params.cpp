// Collision-avoidance-manoeuvre planner parameter table (include/evade/cam/cam_params.hpp).
#include "evade/cam/cam_params.hpp"

namespace evade::cam {
namespace {

const Param<CamConfig> kCamRows[] = {
    EVADE_PARAM_REAL(CamConfig, max_dv_mps, "m/s", 0.0, 1000.0, true,
                     "largest impulsive |dv| the avoidance planner may use (cap)"),
    EVADE_PARAM_REAL(CamConfig, max_lead_s, "s", 0.0, 864000.0, true,
                     "longest lead time before TCA the planner accepts (two-body + J2, no drag)"),
    EVADE_PARAM_REAL(CamConfig, pc_margin, "-", 0.0, 0.5, false,
                     "the planner aims at pc_max x (1 - margin) so the verified Pc stays under pc_max"),
    EVADE_PARAM_REAL(CamConfig, miss_margin_m, "m", 0.0, 1000.0, false,
                     "the planner aims at min_miss_m + this (10 x the 1 mm propagation accuracy)"),
    EVADE_PARAM_INT(CamConfig, boundary_angles, "-", 8, 100000,
                    "directions of the encounter-plane sweep that starts the minimum-dv search"),
    EVADE_PARAM_INT(CamConfig, max_relinearizations, "-", 1, 100,
                    "re-linearizations of the encounter about the burned trajectory"),
    EVADE_PARAM_REAL(CamConfig, dv_tol_mps, "m/s", 0.0, 1.0, true,
                     "re-linearization stops when the burn changes by less than this"),
    EVADE_PARAM_INT(CamConfig, max_target_corrections, "-", 0, 50,
                    "re-plans with the 2D target scaled by 2D/recommended Pc when the verified "
                    "recommended Pc (3D-Nc or Monte Carlo) exceeds pc_max"),
};

}  // namespace

ParamTable<CamConfig> cam_params() noexcept { return make_param_table(kCamRows); }

}  // namespace evade::cam
