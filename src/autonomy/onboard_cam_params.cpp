// The onboard avoidance burn's parameter table (include/evade/autonomy/onboard_cam.hpp): the
// one declaration of each OnboardCamOptions field's unit, range and meaning; cam_options_ok and
// the node's node.autonomy.cam.* keys read it.
#include "evade/autonomy/onboard_cam.hpp"

namespace evade::autonomy {
namespace {

using O = OnboardCamOptions;

const Param<O> kRows[] = {
    EVADE_PARAM_INT(O, burn_times, "-", 1, OnboardCamOptions::kMaxBurnTimes,
                    "candidate burn times spread over the window"),
    EVADE_PARAM_INT(O, boundary_angles, "-", 8, 720, "directions of the Pc = target boundary sweep"),
    EVADE_PARAM_INT(O, bisections, "-", 10, 100, "root steps of the boundary radius along a direction"),
    EVADE_PARAM_INT(O, golden_iterations, "-", 0, 100, "golden-section steps refining each local minimum"),
    EVADE_PARAM_INT(O, relinearizations, "-", 1, 20, "models rebuilt about the burned trajectory"),
    EVADE_PARAM_INT(O, target_corrections, "-", 0, 10, "aims lowered after the exact outcome"),
    EVADE_PARAM_REAL(O, step_s, "s", 0.0, 60.0, true, "RK4 step of every onboard propagation"),
    EVADE_PARAM_REAL(O, max_dv_mps, "m/s", 0.0, 100.0, true, "largest avoidance burn"),
    EVADE_PARAM_REAL(O, pc_margin, "-", 0.0, 0.5, false, "the aim is the post-burn target x (1 - margin)"),
    EVADE_PARAM_REAL(O, dv_tol_mps, "m/s", 0.0, 1.0, true, "convergence of the re-linearization"),
    EVADE_PARAM_REAL(O, min_lead_s, "s", 0.0, 86400.0, false, "no burn sooner than this after now"),
    EVADE_PARAM_REAL(O, pc_rel_tol, "-", 1e-14, 1e-2, false, "relative tolerance of the 2D Pc quadrature"),
};

}  // namespace

ParamTable<OnboardCamOptions> cam_options_params() noexcept { return make_param_table(kRows); }

}  // namespace evade::autonomy
