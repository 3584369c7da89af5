// The SDP4 resonance integrator resumes from checkpoints of its own loop (deep_space.hpp):
// the mean elements at every t must be the loop-from-epoch numbers bit for bit, for both
// resonances, before, inside and beyond the checkpoints' horizon.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <limits>

#include "evade/sgp4/deep_space.hpp"

namespace evade::sgp4 {
namespace {

constexpr double kTwoPi = 6.283185307179586;

DeepSpaceEpoch resonant_epoch(double period_min, double ecco, double inclo_rad) {
  DeepSpaceEpoch ep;
  ep.epoch_days_1950 = 27700.25;
  ep.ecco = ecco;
  ep.inclo = inclo_rad;
  ep.nodeo = 1.1;
  ep.argpo = 4.7;
  ep.mo = 0.3;
  ep.no_unkozai = kTwoPi / period_min;
  ep.mdot = ep.no_unkozai;
  ep.nodedot = -2e-7;
  ep.argpdot = 3e-7;
  ep.gsto = 2.2;
  ep.xke = 0.0743669161331734;
  return ep;
}

void expect_same_as_loop_from_epoch(const DeepSpaceEpoch& ep, int irez) {
  const DeepSpaceTerms with = deep_space_init(ep);
  ASSERT_EQ(with.resonance.irez, irez);
  ASSERT_EQ(with.checkpoints.size(), static_cast<std::size_t>(kResonanceCheckpointHorizonMin / 720.0) + 1);
  DeepSpaceTerms without = with;
  without.checkpoints.clear();  // deep_space_secular then integrates from the epoch
  long checked = 0;
  for (double t = -3000.0; t <= 1.5 * kResonanceCheckpointHorizonMin; t += 97.3) {
    DeepSpaceMean a, b;
    a.nm = b.nm = ep.no_unkozai;
    deep_space_secular(with, ep, t, a);
    deep_space_secular(without, ep, t, b);
    ASSERT_EQ(a.nm, b.nm) << "t = " << t;
    ASSERT_EQ(a.mm, b.mm) << "t = " << t;
    ASSERT_EQ(a.em, b.em);
    ASSERT_EQ(a.argpm, b.argpm);
    ASSERT_EQ(a.nodem, b.nodem);
    ASSERT_EQ(a.inclm, b.inclm);
    ++checked;
  }
  EXPECT_GT(checked, 1000);
}

TEST(ResonanceCheckpoints, SynchronousOrbitGivesTheLoopsNumbersBitForBit) {
  expect_same_as_loop_from_epoch(resonant_epoch(1436.0, 0.0004, 0.02), 1);
}

TEST(ResonanceCheckpoints, HalfDayOrbitGivesTheLoopsNumbersBitForBit) {
  expect_same_as_loop_from_epoch(resonant_epoch(718.0, 0.72, 1.1065), 2);
}

TEST(ResonanceCheckpoints, NonFiniteTimeEndsWithoutAMeanMotionInsteadOfLoopingForever) {
  const DeepSpaceEpoch ep = resonant_epoch(1436.0, 0.0004, 0.02);
  const DeepSpaceTerms ds = deep_space_init(ep);
  for (const double t : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    DeepSpaceMean m;
    m.nm = ep.no_unkozai;
    deep_space_secular(ds, ep, t, m);
    EXPECT_TRUE(std::isnan(m.nm));
  }
}

TEST(ResonanceCheckpoints, NoneWithoutResonance) {
  EXPECT_TRUE(deep_space_init(resonant_epoch(600.0, 0.1, 0.9)).checkpoints.empty());
}

}  // namespace
}  // namespace evade::sgp4
