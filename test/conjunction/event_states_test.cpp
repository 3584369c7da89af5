// event_states: the two objects' states at an event's TCA, from the motion the screener used,
// reproduce the screener's miss distance and relative speed: exactly (to rounding) for
// two-body motion (both use the analytic Kepler propagation), and to the integration error
// for two-body + J2 (the screener reached the TCA through its grid arcs, event_states
// integrates from t = 0 straight to it, both with DOP853 at rel_tol 1e-13, abs_tol 1e-9,
// whose measured global error is ~1e-4 m over a day in LEO: adaptive_options.hpp). The bound used,
// 1 mm on the distance and 1e-6 m/s on the speed, is that error with a margin of 10.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "evade/conjunction/event_states.hpp"
#include "evade/conjunction/population.hpp"
#include "evade/conjunction/robust_screen.hpp"

namespace evade::conjunction {
namespace {

void expect_states_reproduce_events(GravityModel gravity, double tol_m, double tol_mps) {
  PopulationOptions pop;
  pop.count = 60;
  pop.seed = 2;
  pop.span_s = 7200.0;
  pop.coorbital_fraction = 0.2;
  pop.crossing_fraction = 0.2;
  const auto objects = synthetic_population(pop);
  ScreenOptions opt;
  opt.threshold_m = 5000.0;
  opt.step_s = 60.0;
  opt.threads = 1;
  opt.gravity = gravity;
  const ScreenResult r = screen_robust(objects, 7200.0, opt);
  ASSERT_GE(r.events.size(), 3u) << "too few events to test";
  double worst_m = 0.0, worst_mps = 0.0;
  for (const auto& c : r.events) {
    const auto s = event_states(objects, c, opt);
    const double miss = (s[1].r_eci_m - s[0].r_eci_m).norm();
    const double speed = (s[1].v_eci_mps - s[0].v_eci_mps).norm();
    worst_m = std::max(worst_m, std::abs(miss - c.miss_m));
    worst_mps = std::max(worst_mps, std::abs(speed - c.rel_speed_mps));
    EXPECT_NEAR(miss, c.miss_m, tol_m) << objects[c.i].name << "-" << objects[c.j].name;
    EXPECT_NEAR(speed, c.rel_speed_mps, tol_mps) << objects[c.i].name << "-" << objects[c.j].name;
  }
  std::printf("%zu events: worst |miss difference| %.3e m, |speed difference| %.3e m/s\n",
              r.events.size(), worst_m, worst_mps);
}

TEST(EventStates, TwoBodyReproducesMissAndSpeed) {
  expect_states_reproduce_events(GravityModel::kTwoBody, 1e-6, 1e-9);
}

TEST(EventStates, J2ReproducesMissAndSpeedToIntegrationError) {
  expect_states_reproduce_events(GravityModel::kTwoBodyJ2, 1e-3, 1e-6);
}

TEST(EventStates, IndexOutOfRangeIsRefused) {
  std::vector<SpaceObject> objects(2);
  objects[0].state = {Vec3(7e6, 0, 0), Vec3(0, 7546, 0)};
  objects[1].state = {Vec3(0, 7e6, 0), Vec3(-7546, 0, 0)};
  Conjunction c;
  c.i = 0;
  c.j = 5;
  EXPECT_THROW(event_states(objects, c, ScreenOptions{}), std::invalid_argument);
}

}  // namespace
}  // namespace evade::conjunction
