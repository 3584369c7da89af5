// The 3D-Nc collision rate dNc/dt at one time (private to pc_3d_nc.cpp and its time integral,
// nc_time_integral.hpp; the method and the equations are in pc_3d_nc.cpp's header).
#pragma once

#include "evade/core/state.hpp"

namespace evade::assessment::nc {

/// One object's Gaussian PDF in equinoctial elements at TCA (t = 0).
struct ElementPdf {
  Vec6 e0 = Vec6::Zero();  ///< mean elements (n, af, ag, chi, psi, lambda_M)
  Mat6 q = Mat6::Zero();   ///< element covariance
};

struct RateSettings {
  double hbr_m = 0.0;
  double mu_m3ps2 = 0.0;
  double sphere_rel_tol = 1e-6;  ///< relative accuracy of the unit-sphere integral
};

struct Rate {
  double rate_per_s = 0.0;        ///< dNc/dt, the unit-sphere integral
  double rate_small_per_s = 0.0;  ///< dNc/dt in the small-HBR limit
  double ms2 = 0.0;               ///< effective Mahalanobis distance^2 to the sphere surface
  bool pop_converged = true;      ///< the peak-overlap iteration converged
  bool sphere_converged = true;   ///< successive sphere rules agreed to the tolerance
  double sphere_error_per_s = 0.0;  ///< |difference| of the last two sphere rules
  int pop_iterations = 0;
  int sphere_points = 0;          ///< integrand evaluations on the sphere
};

/// dNc/dt at t_s about TCA. abs_floor_per_s: an absolute accuracy that suffices for the
/// sphere integral (a small fraction of the largest rate seen so far).
Rate collision_rate(const ElementPdf& obj1, const ElementPdf& obj2, double t_s,
                    const RateSettings& s, double abs_floor_per_s);

}  // namespace evade::assessment::nc
