// The J2 no-miss bound (docs/VALIDATION.md, "Robust mode under J2: the no-miss bound")
// against the fine-sampling reference (reference_screen.hpp: every pair's range rate every
// 1 s, each - to + sign change refined by Brent's method) on seeded 500-object populations
// with slow co-orbital pairs, crossing pairs and near-tangent pairs, over 1 day and 7 days
// under two-body + J2. Requirement: zero misses (and nothing the reference does not find).
// An approach is the same if the pair matches, the TCAs agree within 1 ms and the misses
// within 1 cm (both locate the same root of the same force model; the integrations differ
// by < 1 mm).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <tuple>

#include "evade/conjunction/population.hpp"
#include "evade/conjunction/reference_screen.hpp"
#include "evade/conjunction/robust_screen.hpp"

namespace evade::conjunction {
namespace {

bool contains(const std::vector<Conjunction>& events, const Conjunction& want) {
  for (const auto& e : events) {
    if (e.i == want.i && e.j == want.j && std::abs(e.tca_s - want.tca_s) < 1e-3 &&
        std::abs(e.miss_m - want.miss_m) < 0.01) {
      return true;
    }
  }
  return false;
}

// (seed, span in days)
class J2NoMiss : public ::testing::TestWithParam<std::tuple<int, int>> {};

TEST_P(J2NoMiss, RobustFindsEveryReferenceApproach) {
  const auto [seed, days] = GetParam();
  const double span_s = 86400.0 * days;
  PopulationOptions pop;
  pop.count = 500;
  pop.seed = static_cast<std::uint64_t>(seed);
  pop.span_s = span_s;
  pop.coorbital_fraction = 0.08;  // 20 slow co-orbital pairs
  pop.crossing_fraction = 0.08;   // 20 crossing pairs
  pop.tangent_fraction = 0.08;    // 20 near-tangent pairs
  const auto objects = synthetic_population(pop);
  ScreenOptions opt;
  opt.gravity = GravityModel::kTwoBodyJ2;
  opt.threshold_m = 5000.0;
  opt.step_s = 60.0;
  opt.threads = 2;
  const ScreenResult robust = screen_robust(objects, span_s, opt);
  const ScreenResult ref = screen_reference(objects, span_s, 1.0, opt);
  int slow = 0, tangent = 0;
  for (const auto& e : ref.events) {
    EXPECT_TRUE(contains(robust.events, e))
        << "missed: pair " << e.i << "-" << e.j << " tca " << e.tca_s << " miss " << e.miss_m;
    slow += e.rel_speed_mps < 100.0 ? 1 : 0;
    tangent += objects[e.i].name.rfind("tg", 0) == 0 && objects[e.j].name.rfind("tg", 0) == 0;
  }
  for (const auto& e : robust.events) {
    EXPECT_TRUE(contains(ref.events, e)) << "extra: " << e.i << "-" << e.j << " tca " << e.tca_s;
  }
  EXPECT_GT(slow, 10) << "too few slow approaches to test";
  EXPECT_GT(tangent, 5) << "too few near-tangent approaches to test";
  std::printf("seed %d, %d day(s): %zu reference approaches (%d slow < 100 m/s, %d near-tangent), "
              "%zu robust, %ld unproven leaves\n",
              seed, days, ref.events.size(), slow, tangent, robust.events.size(),
              robust.stats.unproven_leaves);
}

INSTANTIATE_TEST_SUITE_P(Populations, J2NoMiss,
                         ::testing::Values(std::make_tuple(101, 1), std::make_tuple(102, 1),
                                           std::make_tuple(201, 7), std::make_tuple(202, 7),
                                           std::make_tuple(203, 7)));

}  // namespace
}  // namespace evade::conjunction
