// OrbitRhs (orbit_rhs.hpp) is orbit_derivative inlined: the same values bit for bit, so an
// integration with it takes the same steps and reaches the same states.
#include <gtest/gtest.h>

#include <functional>

#include "evade/dynamics/dop853.hpp"
#include "evade/dynamics/gravity.hpp"
#include "evade/dynamics/orbit_rhs.hpp"
#include "test_orbits.hpp"

namespace evade {
namespace {

TEST(OrbitRhs, EqualsOrbitDerivativeBitForBit) {
  for (GravityModel model : {GravityModel::kTwoBody, GravityModel::kTwoBodyJ2}) {
    const OrbitRhs rhs{model, kEarthDefault};
    for (const StateEci& s : {test::leo_e01(), test::orbit_state(6900e3, 0.001, 1.5, 0.2, 0.0, 2.0)}) {
      Vec6 x = s.stacked();
      for (int k = 0; k < 50; ++k) {
        x.head<3>() *= 1.0 + 1e-3 * k;   // spread the radius and the latitude a little
        x[2] += 1e4 * k;
        const Vec6 a = rhs(0.0, x);
        const Vec6 b = orbit_derivative(x, model, kEarthDefault);
        for (int c = 0; c < 6; ++c) ASSERT_EQ(a[c], b[c]) << "component " << c << ", k " << k;
      }
    }
  }
}

TEST(OrbitRhs, IntegrationTakesTheSameStepsAsWithStdFunction) {
  const EarthModel earth = kEarthDefault;
  Dop853<Vec6> generic([earth](double, const Vec6& x) {
    return orbit_derivative(x, GravityModel::kTwoBodyJ2, earth);
  }, AdaptiveOptions::tight());
  Dop853<Vec6, OrbitRhs> inlined(OrbitRhs{GravityModel::kTwoBodyJ2, earth}, AdaptiveOptions::tight());
  generic.reset(0.0, test::leo_e01().stacked());
  inlined.reset(0.0, test::leo_e01().stacked());
  for (int k = 0; k < 300; ++k) {
    ASSERT_TRUE(generic.step(86400.0));
    ASSERT_TRUE(inlined.step(86400.0));
    ASSERT_EQ(generic.t_s(), inlined.t_s());
    const double tm = 0.5 * (generic.t_prev_s() + generic.t_s());
    for (int c = 0; c < 6; ++c) {
      ASSERT_EQ(generic.x()[c], inlined.x()[c]);
      ASSERT_EQ(generic.dense(tm)[c], inlined.dense(tm)[c]);
    }
  }
}

}  // namespace
}  // namespace evade
