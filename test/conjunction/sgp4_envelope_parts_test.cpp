// The perturbation envelopes split between processes (Sgp4MotionOptions::part, parts and
// sum_over_parts; issue 24's MPI setup): each process samples the element sets k with
// k mod parts == part, and the element-wise sum over the processes gives every process the
// envelopes one process computes alone, bit for bit, SGP4 failures (and so the rejections)
// included. The two processes are simulated here: part 1 first, whose vector part 0's sum
// then adds.
#include <gtest/gtest.h>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "evade/conjunction/sgp4_motion.hpp"
#include "sgp4_test_catalog.hpp"

namespace evade::conjunction {
namespace {

std::vector<sgp4::MeanElements> catalog_with_a_decaying_object() {
  const std::vector<sgp4::MeanElements> all = testing::shipped_catalog().objects;
  std::vector<sgp4::MeanElements> cat;
  for (std::size_t k = 0; k < all.size(); k += 8) cat.push_back(all[k]);  // 150, LEO to HEO
  // A LEO element set with a drag term that brings it down within the span: its envelope
  // sampling stops at an SGP4 error, which the other process must learn of.
  for (const sgp4::MeanElements& m : all) {
    if (m.mean_motion_revpday > 15.0 && m.eccentricity < 0.01) {
      cat.push_back(m);
      cat.back().bstar_per_er = 0.5;
      break;
    }
  }
  return cat;
}

Sgp4MotionOptions options() {
  Sgp4MotionOptions o;
  o.span_s = 7.0 * 86400.0;
  o.threads = 2;
  return o;
}

TEST(EnvelopeParts, TwoPartsSummedGiveTheEnvelopesOfOneProcessBitForBit) {
  const std::vector<sgp4::MeanElements> cat = catalog_with_a_decaying_object();
  const Sgp4Screening one = sgp4_screening(cat, options());
  ASSERT_FALSE(one.rejected.empty()) << "the decaying element set should be rejected";
  EXPECT_NE(one.rejected.back().reason.find("s from the start"), std::string::npos)
      << "rejected at a sample, not at initialisation: " << one.rejected.back().reason;
  EXPECT_EQ(one.envelopes_sampled, static_cast<long>(cat.size()));

  std::vector<double> part1;
  Sgp4MotionOptions o1 = options();
  o1.part = 1;
  o1.parts = 2;
  o1.sum_over_parts = [&part1](std::vector<double>& v) { part1 = v; };
  const Sgp4Screening alone1 = sgp4_screening(cat, o1);
  EXPECT_EQ(alone1.envelopes_sampled, static_cast<long>(cat.size() / 2));

  std::vector<double> part0;
  Sgp4MotionOptions o0 = o1;
  o0.part = 0;
  o0.sum_over_parts = [&part0, &part1](std::vector<double>& v) {
    part0 = v;
    ASSERT_EQ(v.size(), part1.size());
    for (std::size_t k = 0; k < v.size(); ++k) v[k] += part1[k];
  };
  const Sgp4Screening two = sgp4_screening(cat, o0);
  EXPECT_EQ(two.envelopes_sampled, static_cast<long>((cat.size() + 1) / 2));

  // Each process wrote only its own element sets' records.
  ASSERT_EQ(part0.size(), cat.size() * kEnvelopeRecord);
  long written0 = 0, written1 = 0;
  for (std::size_t k = 0; k < cat.size(); ++k) {
    for (std::size_t f = 0; f < kEnvelopeRecord; ++f) {
      const double a = part0[k * kEnvelopeRecord + f], b = part1[k * kEnvelopeRecord + f];
      EXPECT_TRUE(a == 0.0 || b == 0.0) << "element set " << k << " sampled by both";
      written0 += a != 0.0 ? 1 : 0;
      written1 += b != 0.0 ? 1 : 0;
      EXPECT_EQ(k % 2 == 0 ? b : a, 0.0) << "element set " << k << " sampled by the other part";
    }
  }
  EXPECT_GT(written0, 0);
  EXPECT_GT(written1, 0);

  ASSERT_EQ(two.objects.size(), one.objects.size());
  ASSERT_EQ(two.rejected.size(), one.rejected.size());
  for (std::size_t r = 0; r < one.rejected.size(); ++r) EXPECT_EQ(two.rejected[r].message(), one.rejected[r].message());
  for (std::size_t i = 0; i < one.objects.size(); ++i) {
    EXPECT_EQ(two.motion->perturbation(i).accel_mps2, one.motion->perturbation(i).accel_mps2) << i;
    EXPECT_EQ(two.motion->perturbation(i).rate_mps3, one.motion->perturbation(i).rate_mps3) << i;
    EXPECT_EQ(two.motion->sampled_perturbation_mps2(i), one.motion->sampled_perturbation_mps2(i)) << i;
  }
}

TEST(EnvelopeParts, RefusesAPartOutsideTheProcessesOrPartsWithoutASum) {
  const std::vector<sgp4::MeanElements> cat = catalog_with_a_decaying_object();
  Sgp4MotionOptions o = options();
  o.parts = 2;
  EXPECT_THROW((void)sgp4_screening(cat, o), std::invalid_argument);  // no sum_over_parts
  o.sum_over_parts = [](std::vector<double>&) {};
  o.part = 2;
  EXPECT_THROW((void)sgp4_screening(cat, o), std::invalid_argument);
  o.part = -1;
  EXPECT_THROW((void)sgp4_screening(cat, o), std::invalid_argument);
  o.part = 0;
  o.parts = 0;
  EXPECT_THROW((void)sgp4_screening(cat, o), std::invalid_argument);
}

TEST(EnvelopeParts, ASumThatChangesTheVectorsSizeOrGarblesAnErrorCodeIsAnError) {
  Sgp4MotionOptions o = options();
  o.parts = 2;
  o.sum_over_parts = [](std::vector<double>& v) { v.pop_back(); };
  EXPECT_THROW((void)sgp4_screening(catalog_with_a_decaying_object(), o), std::logic_error);
  // Both parts reporting the decaying element set's failure: its code summed to 12.
  o.sum_over_parts = [](std::vector<double>& v) {
    for (std::size_t k = 2; k < v.size(); k += kEnvelopeRecord) v[k] *= 2.0;
  };
  o.part = 1;  // the decaying element set is the last one, index 150: part 0's
  EXPECT_NO_THROW((void)sgp4_screening(catalog_with_a_decaying_object(), o));  // nothing failed here
  o.part = 0;
  EXPECT_THROW((void)sgp4_screening(catalog_with_a_decaying_object(), o), std::logic_error);
}

}  // namespace
}  // namespace evade::conjunction
