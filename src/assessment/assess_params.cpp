// Assessment parameter table (include/evade/assessment/assess_params.hpp).
#include "evade/assessment/assess_params.hpp"

namespace evade::assessment {
namespace {

const Param<AssessConfig> kRows[] = {
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
};

}  // namespace

ParamTable<AssessConfig> assess_params() noexcept { return make_param_table(kRows); }

}  // namespace evade::assessment
