// Assessment parameter table (include/evade/assessment/assess_params.hpp).
#include "evade/assessment/assess_params.hpp"

namespace evade::assessment {
namespace {

const Param<AssessConfig> kAssessRows[] = {
    EVADE_PARAM_REAL(AssessConfig, pc_rel_tol, "-", 1e-14, 1e-2, false,
                     "relative tolerance of the 2D Pc quadrature"),
    EVADE_PARAM_REAL(AssessConfig, short_term_max_period_fraction, "-", 0.0, 1.0, true,
                     "short-term encounter holds while encounter time <= this x orbital period"),
    EVADE_PARAM_REAL(AssessConfig, short_term_max_vel_sigma_ratio, "-", 0.0, 10.0, true,
                     "short-term encounter holds while sigma(v_rel) <= this x v_rel"),
    EVADE_PARAM_REAL(AssessConfig, mc_window_sigmas, "-", 1.0, 100.0, false,
                     "Monte Carlo window half-width (k sigma_max + HBR) / v_rel, at most P/2"),
    EVADE_PARAM_REAL(AssessConfig, tca_search_s, "s", 0.0, 86400.0, false,
                     "largest shift from the given state epoch to the local TCA (0: use the states as given)"),
    with_flag(EVADE_PARAM_REAL(AssessConfig, window_s, "s", 0.0, 1e7, false,
                               "3D-Nc and Monte Carlo window [-S, +S] about TCA (0: from the covariances)"),
              "--window-s"),
    EVADE_PARAM_REAL(AssessConfig, conj_duration_gamma, "-", 1e-300, 0.5, true,
                     "probability left outside the conjunction-duration bounds (Coppola 2012)"),
    EVADE_PARAM_REAL(AssessConfig, pc2d_extended_cutoff, "-", 0.0, 1.0, false,
                     "2D usage check fails when conjunction duration / shorter period exceeds this"),
    EVADE_PARAM_REAL(AssessConfig, pc2d_offset_cutoff, "-", 0.0, 1.0, false,
                     "2D usage check fails when the farthest bound from TCA / shorter period exceeds this"),
    EVADE_PARAM_REAL(AssessConfig, nc3d_extended_cutoff, "-", 0.0, 1.0, false,
                     "3D-Nc check fails when conjunction span / encounter segment exceeds this"),
    EVADE_PARAM_REAL(AssessConfig, nc3d_offset_cutoff, "-", 0.0, 1.0, false,
                     "3D-Nc check fails when a conjunction bound / segment bound exceeds this"),
    EVADE_PARAM_REAL(AssessConfig, mc_target_rel_accuracy, "-", 0.0, 1.0, true,
                     "escalated Monte Carlo stops when the 95 % half-width is within this x Pc"),
    with_flag(EVADE_PARAM_INT(AssessConfig, mc_max_samples, "-", 10000, 1000000000,
                              "escalated Monte Carlo: largest number of samples"),
              "--mc-max-samples"),
    EVADE_PARAM_BOOL(AssessConfig, mc_j2,
                     "Monte Carlo samples move by two-body + J2 (DOP853) instead of two-body"),
};

}  // namespace

ParamTable<AssessConfig> assess_params() noexcept { return make_param_table(kAssessRows); }

}  // namespace evade::assessment
