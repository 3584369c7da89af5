// Parameters of conjunction assessment (key prefix
// "assessment."), read with config::read_params; the one place their ranges live.
#pragma once

#include "evade/core/param.hpp"

namespace evade::assessment {

struct AssessConfig {
  double pc_rel_tol = 1e-8;                     ///< relative tolerance of the 2D Pc quadrature
  double short_term_max_period_fraction = 0.01; ///< encounter time / orbital period allowed
  double short_term_max_vel_sigma_ratio = 0.1;  ///< sigma(relative speed) / relative speed allowed
  double mc_window_sigmas = 8.0;                ///< MC window: (k sigma_max + HBR) / v_rel
  double tca_search_s = 600.0;                  ///< largest shift from the given epoch to TCA [s]
};

ParamTable<AssessConfig> assess_params() noexcept;

}  // namespace evade::assessment
