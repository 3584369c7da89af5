// The parameter tables of paper 003's planning inputs (see plan_inputs.hpp).
#include "evade/formation/plan_inputs.hpp"

namespace evade::formation {
namespace {

const Param<FormationParams> kFormationRows[] = {
    EVADE_PARAM_REAL(FormationParams, side_length_m, "m", 1.0, 1e7, false,
                     "L: side of the nominal equilateral triangle"),
    EVADE_PARAM_REAL(FormationParams, box_delta_m, "m", 1e-3, 1e7 / 8.0, false,
                     "control-box unit (at most side_length_m / 8)"),
    EVADE_PARAM_REAL(FormationParams, raan_tolerance_deg, "deg", 1e-9, 90.0, false,
                     "inter-group RAAN tolerance"),
    EVADE_PARAM_REAL(FormationParams, phase_tolerance_deg, "deg", 1e-9, 90.0, false,
                     "inter-group phase tolerance"),
    EVADE_PARAM_REAL(FormationParams, horizon_days, "day", 1e-3, 60.0, false,
                     "T: time until the next formation-keeping burn"),
};

const Param<PropagationParams> kPropagationRows[] = {
    EVADE_PARAM_REAL(PropagationParams, rel_tol, "-", 1e-14, 1e-6, false,
                     "DOP853 relative tolerance"),
    EVADE_PARAM_REAL(PropagationParams, abs_tol_m, "m", 1e-12, 10.0, false,
                     "DOP853 absolute tolerance (m and m/s)"),
    EVADE_PARAM_INT(PropagationParams, samples_per_rev, "-", 8, 512,
                    "samples per nodal period for the element averaging"),
};

}  // namespace

ParamTable<FormationParams> formation_params() noexcept { return make_param_table(kFormationRows); }

ParamTable<PropagationParams> propagation_params() noexcept {
  return make_param_table(kPropagationRows);
}

}  // namespace evade::formation
