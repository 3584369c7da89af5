// The constructed LEO conjunction of the onboard burn's tests (onboard_cam_test.cpp,
// response_test.cpp): scenarios/cam-example.yaml's states at TCA (700 km, a 27 deg crossing at
// 3.5 km/s, miss 126 m, Pc about 1e-3) with axis-aligned covariances (the example's RTN sigmas
// on the ECI axes: its primary is at [r, 0, 0], so R, T, N are nearly x, y, z); TCA 4 lead
// times after kNow, the burn window 1.2 to 0.8 lead times before TCA.
#pragma once

#include <cstdint>

#include "evade/autonomy/conjunction_event.hpp"

namespace evade::autonomy::test_example {

constexpr std::int64_t kNow = 1'000'000'000'000;
constexpr double kLeadS = 9000.0;  // about 1.5 orbits of the 700 km primary

inline Mat6 diag_cov(double r, double t, double n) {
  Mat6 c = Mat6::Zero();
  c.diagonal() << r * r, t * t, n * n, 1e-4, 1e-4, 1e-4;
  return c;
}

/// Red threshold and post-burn target 1e-4; the veto deadline at the window's start.
inline ConjunctionEvent example_event(std::int64_t id = 7) {
  ConjunctionEvent e;
  e.event_id = id;
  e.version = 1;
  e.tca_us = kNow + static_cast<std::int64_t>(4.0 * kLeadS * 1e6);
  e.x1_eci << 7078137.0, 0.0, 0.0, 0.0, -1070.3284, 7427.5644;
  e.x2_eci << 7078177.0, -11.293, -119.467, 0.0, 2443.1567, 7095.4423;
  e.cov1_eci = diag_cov(30.0, 150.0, 20.0);
  e.cov2_eci = diag_cov(80.0, 600.0, 60.0);
  e.hbr_m = 15.0;
  e.pc_red = 1e-4;
  e.pc_target = 1e-4;
  e.burn_start_us = e.tca_us - static_cast<std::int64_t>(1.2 * kLeadS * 1e6);
  e.burn_end_us = e.tca_us - static_cast<std::int64_t>(0.8 * kLeadS * 1e6);
  e.veto_deadline_us = e.burn_start_us;
  return e;
}

}  // namespace evade::autonomy::test_example
