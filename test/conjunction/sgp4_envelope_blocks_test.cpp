// The perturbation envelope sampled over one orbit every envelope_block_gap_s and the last
// orbit (sgp4_motion.hpp) against the same envelope sampled over every orbit of the span: on
// the shipped catalog (LEO, MEO, GEO, HEO; SGP4 and SDP4) the block envelope's largest |p|
// is within a few per cent of every orbit's (the bound is then twice it plus the floor: the
// margin the theorem's assumption S1 keeps, docs/VALIDATION.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "evade/conjunction/sgp4_motion.hpp"
#include "sgp4_test_catalog.hpp"

namespace evade::conjunction {
namespace {

std::vector<sgp4::MeanElements> shipped() { return testing::shipped_catalog().objects; }

TEST(EnvelopeSampleTimes, EveryOrbitWhenTheGapIsZeroOneOrbitPerGapOtherwise) {
  Sgp4MotionOptions o;
  o.span_s = 86400.0;
  o.samples_per_orbit = 64;
  o.envelope_block_gap_s = 0.0;
  const std::vector<double> every = envelope_sample_times(5760.0, 0.0, o);
  EXPECT_EQ(every.size(), 64u * 15u + 1u);  // 90 s apart over the day, both ends
  EXPECT_DOUBLE_EQ(every.front(), 0.0);
  EXPECT_DOUBLE_EQ(every.back(), 86400.0);
  o.envelope_block_gap_s = 21600.0;
  const std::vector<double> blocks = envelope_sample_times(5760.0, 0.0, o);
  // Orbits starting at 0, 6 h, 12 h, 18 h and the last orbit [span - P, span]: 5 x 65.
  EXPECT_EQ(blocks.size(), 5u * 65u);
  EXPECT_DOUBLE_EQ(blocks.back(), 86400.0);
  EXPECT_TRUE(std::is_sorted(blocks.begin(), blocks.end()));
  // A gap no longer than the orbit samples every orbit.
  o.envelope_block_gap_s = 5000.0;
  EXPECT_EQ(envelope_sample_times(5760.0, 0.0, o), every);
}

TEST(EnvelopeBlocks, LargestPerturbationWithinFivePerCentOfEveryOrbitOnTheShippedCatalog) {
  // EVADE_ENVELOPE_FULL=1: all 1,200 objects over 7 days (docs/VALIDATION.md's figure).
  const bool full = std::getenv("EVADE_ENVELOPE_FULL") != nullptr;
  const std::vector<sgp4::MeanElements> all = shipped();
  std::vector<sgp4::MeanElements> cat;
  for (std::size_t k = 0; k < all.size(); k += full ? 1 : 4) cat.push_back(all[k]);  // 300
  Sgp4MotionOptions every;
  every.span_s = (full ? 7.0 : 3.0) * 86400.0;
  every.threads = 2;
  every.envelope_block_gap_s = 0.0;
  Sgp4MotionOptions blocks = every;
  blocks.envelope_block_gap_s = 21600.0;
  const Sgp4Screening a = sgp4_screening(cat, every);
  const Sgp4Screening b = sgp4_screening(cat, blocks);
  ASSERT_EQ(a.objects.size(), b.objects.size());
  double worst = 1.0;
  std::size_t worst_i = 0;
  for (std::size_t i = 0; i < a.objects.size(); ++i) {
    const double ratio = b.motion->sampled_perturbation_mps2(i) / a.motion->sampled_perturbation_mps2(i);
    if (ratio < worst) {
      worst = ratio;
      worst_i = i;
    }
  }
  std::printf("%zu objects, %.0f days: smallest block / every-orbit largest |p| = %.4f (%s)\n",
              a.objects.size(), every.span_s / 86400.0, worst, a.objects[worst_i].name.c_str());
  EXPECT_GT(worst, 0.95);
}

}  // namespace
}  // namespace evade::conjunction
