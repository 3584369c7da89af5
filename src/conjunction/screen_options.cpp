// ScreenOptions of the robust screener (robust_screen.hpp): the scenario's `robust.*`
// parameter table (threshold_m, step_s, leaf_s; docs/PARAMETERS.md is generated from it), the
// checks of every option (validate), and the automatic grid step auto_step_s (calibration in
// docs/PERFORMANCE.md). D_ij = max(D, N R_c) with R_c of eq. 1 of Wang Xiaoyu, "Space entity
// collision prediction algorithm and self-adaptive simulation step design", J. Air Force Eng.
// Univ. 7(6), 2006 (paper 002).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <stdexcept>
#include <string>

#include "evade/conjunction/robust_screen.hpp"
#include "evade/core/earth_params.hpp"

namespace evade::conjunction {
namespace {

const Param<ScreenOptions> kScreenOptionRows[] = {
    with_flag(EVADE_PARAM_REAL(ScreenOptions, threshold_m, "m", 0.0, 1e8, false,
                               "D: report every closest approach with miss <= max(D, N R_c)"),
              "--threshold-m"),
    with_flag(EVADE_PARAM_REAL(ScreenOptions, step_s, "s", 0.0, 1e5, false,
                               "grid step h of the broad phase (0: auto_step_s(N, motion))"),
              "--step-s"),
    EVADE_PARAM_REAL(ScreenOptions, leaf_s, "s", 1e-6, 1e5, false,
                     "smallest subdivision of the narrow phase"),
};

}  // namespace

ParamTable<ScreenOptions> screen_options_params() noexcept {
  return make_param_table(kScreenOptionRows);
}

void ScreenOptions::validate() const {
  const std::string bad = validate_params(screen_options_params(), *this, "robust.");
  if (!bad.empty()) throw std::invalid_argument(bad);
  auto fail = [](const char* key, double v, const char* range) {
    std::ostringstream os;
    os << "screen." << key << " = " << v << " outside " << range;
    throw std::invalid_argument(os.str());
  };
  if (!(warning_multiple > 1.0) || !std::isfinite(warning_multiple))
    fail("warning_multiple", warning_multiple, "(1, inf)");
  if (!(tca_tol_s > 0.0) || !std::isfinite(tca_tol_s)) fail("tca_tol_s", tca_tol_s, "(0, inf)");
  if (threads < 1 || threads > 256) fail("threads", threads, "[1, 256]");
  if (primary < -1) fail("primary", static_cast<double>(primary), "[-1, objects)");
  if (motion) {
    const EarthModel m = motion->reference_earth();
    if (gravity != GravityModel::kTwoBodyJ2 || m.mu_m3ps2 != earth.mu_m3ps2 || m.re_m != earth.re_m ||
        m.j2 != earth.j2) {
      throw std::invalid_argument(
          "screen.motion: the motion's perturbation bound is measured against two-body + J2 with "
          "its reference Earth model: set gravity = two_body_j2 and earth = reference_earth()");
    }
  }
  const std::string bad_earth = validate_params(earth_params(), earth, "earth.");
  if (!bad_earth.empty()) throw std::invalid_argument(bad_earth);
  integ.validate();
}

double auto_step_s(std::size_t n_objects, bool grid_states) {
  const double n = static_cast<double>(std::max<std::size_t>(n_objects, 1));
  const double h_10k_s = grid_states ? kAutoStepGridStates_s : kAutoStepForceModels_s;
  return std::clamp(h_10k_s * std::cbrt(10000.0 / n), 10.0, 120.0);
}

double auto_step_s(std::size_t n_objects, const ScreenOptions& opt) {
  return auto_step_s(n_objects, opt.motion && opt.motion->has_grid_states());
}

}  // namespace evade::conjunction
