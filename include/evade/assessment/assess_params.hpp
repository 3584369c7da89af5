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
  // Method choice (pc_method_choice.hpp): NASA CARA's multistep cutoffs (Hall et al. 2023).
  double window_s = 0.0;               ///< > 0: 3D-Nc / MC window [-S, +S] about TCA [s]
  double conj_duration_gamma = 1e-16;  ///< probability outside the conjunction bounds
  double pc2d_extended_cutoff = 0.02;  ///< 2D: duration / period above this fails
  double pc2d_offset_cutoff = 0.01;    ///< 2D: farthest bound / period above this fails
  double nc3d_extended_cutoff = 0.5;   ///< 3D-Nc: span / encounter segment above this fails
  double nc3d_offset_cutoff = 0.75;    ///< 3D-Nc: bound / segment bound above this fails
  double mc_target_rel_accuracy = 0.05;  ///< escalated MC: stop at 95 % half-width <= this x Pc
  int mc_max_samples = 10000000;       ///< escalated MC: largest number of samples
  bool mc_j2 = false;                  ///< Monte Carlo with two-body + J2 motion (else two-body)
};

ParamTable<AssessConfig> assess_params() noexcept;

}  // namespace evade::assessment
