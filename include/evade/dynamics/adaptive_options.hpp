// The options and statistics of the adaptive integrator DOP853 (dop853.hpp): tolerances, step
// limits and the step budget, and the counts of steps and right-hand side evaluations.
//
// Default tolerances (AdaptiveOptions{}): rel_tol = 1e-10, abs_tol = 1e-6 (same units as
// the state: m and m/s for an orbit). Measured (test/dynamics/adaptive_vs_kepler_test.cpp):
// position error 0.22 m after 1 day on an e = 0.1, a = 7500 km orbit, i.e. well below the
// promised 1 m. AdaptiveOptions::tight(): rel_tol = 1e-13, abs_tol = 1e-9, measured error 1e-4 m (< 1 mm).
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

namespace evade {

struct AdaptiveOptions {
  double rel_tol = 1e-10;     ///< relative tolerance [-]
  double abs_tol = 1e-6;      ///< absolute tolerance [state units, m and m/s for orbits]
  double h_initial_s = 0.0;   ///< first step [s]; 0 = automatic (Hairer's HINIT)
  double h_max_s = 0.0;       ///< largest step [s]; 0 = no limit
  long max_steps = 10'000'000;  ///< bound on attempted steps (accepted + rejected)

  /// Tolerances giving < 1 mm position error over 1 day for LEO (see the file comment).
  static AdaptiveOptions tight() {
    AdaptiveOptions o;
    o.rel_tol = 1e-13;
    o.abs_tol = 1e-9;
    return o;
  }
  /// Throws std::invalid_argument naming the offending key and value.
  void validate() const {
    auto fail = [](const char* key, double v, const char* range) {
      throw std::invalid_argument(std::string("AdaptiveOptions.") + key + " = " +
                                  std::to_string(v) + " outside " + range);
    };
    if (!(rel_tol >= 0.0) || !std::isfinite(rel_tol)) fail("rel_tol", rel_tol, "[0, inf)");
    if (!(abs_tol >= 0.0) || !std::isfinite(abs_tol)) fail("abs_tol", abs_tol, "[0, inf)");
    if (rel_tol == 0.0 && abs_tol == 0.0) fail("rel_tol", rel_tol, "(0, inf) when abs_tol = 0");
    if (!(h_initial_s >= 0.0) || !std::isfinite(h_initial_s))
      fail("h_initial_s", h_initial_s, "[0, inf)");
    if (!(h_max_s >= 0.0) || !std::isfinite(h_max_s)) fail("h_max_s", h_max_s, "[0, inf)");
    if (max_steps < 1) fail("max_steps", static_cast<double>(max_steps), "[1, inf)");
  }
};

struct IntegrationStats {
  long steps_accepted = 0;
  long steps_rejected = 0;
  long rhs_evaluations = 0;
};

}  // namespace evade
