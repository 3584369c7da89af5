// RK4: fourth-order convergence on problems with a known solution.
#include <gtest/gtest.h>

#include <cmath>

#include "evade/dynamics/gravity.hpp"
#include "evade/dynamics/kepler_propagator.hpp"
#include "evade/dynamics/rk4.hpp"
#include "test_orbits.hpp"

namespace evade {
namespace {

// x' = -x + sin t has solution x = C e^-t + (sin t - cos t)/2; global error O(h^4), so
// halving h divides the error by 2^4 = 16 (asymptotically; we accept 14..18).
TEST(Rk4, ConvergesAtFourthOrderOnScalarOde) {
  auto f = [](double t, const double& x) { return -x + std::sin(t); };
  const double x0 = 1.0;
  const double t1 = 3.0;
  const double c = x0 + 0.5;  // from x(0) = C - 1/2
  const double exact = c * std::exp(-t1) + 0.5 * (std::sin(t1) - std::cos(t1));
  const double e1 = std::abs(rk4_propagate(f, 0.0, x0, t1, 0.1) - exact);
  const double e2 = std::abs(rk4_propagate(f, 0.0, x0, t1, 0.05) - exact);
  const double e3 = std::abs(rk4_propagate(f, 0.0, x0, t1, 0.025) - exact);
  EXPECT_NEAR(e1 / e2, 16.0, 2.0);
  EXPECT_NEAR(e2 / e3, 16.0, 2.0);
}

// Same on the e = 0.1 LEO orbit against Kepler (one orbit, steps of 20, 10, 5 s: at 60 s the
// perigee pass is not yet in the asymptotic regime).
TEST(Rk4, ConvergesAtFourthOrderOnTwoBodyOrbit) {
  const StateEci s0 = test::leo_e01();
  auto f = [](double, const Vec6& x) {
    return orbit_derivative(x, GravityModel::kTwoBody, kEarthDefault);
  };
  const double t1 = 6000.0;
  const Vec3 truth = propagate_kepler(s0, t1, kEarthDefault.mu_m3ps2).r_eci_m;
  double err[3];
  for (int k = 0; k < 3; ++k) {
    const double h = 20.0 / std::pow(2.0, k);
    err[k] = (rk4_propagate(f, 0.0, s0.stacked(), t1, h).head<3>() - truth).norm();
  }
  EXPECT_NEAR(err[0] / err[1], 16.0, 2.0);
  EXPECT_NEAR(err[1] / err[2], 16.0, 2.0);
}

TEST(Rk4, PropagatesBackwardInTime) {
  auto f = [](double, const double& x) { return -x; };
  EXPECT_NEAR(rk4_propagate(f, 1.0, std::exp(-1.0), 0.0, 1e-3), 1.0, 1e-12);
}

TEST(Rk4, RejectsNonPositiveStep) {
  auto f = [](double, const double& x) { return x; };
  EXPECT_THROW(rk4_propagate(f, 0.0, 1.0, 1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(rk4_propagate(f, 0.0, 1.0, 1.0, -1.0), std::invalid_argument);
}

}  // namespace
}  // namespace evade
