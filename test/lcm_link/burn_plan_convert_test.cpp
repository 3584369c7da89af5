// BurnPlan <-> evade_burn_plan_t (guidance_lcm/burn_plan_convert.hpp): a bit-exact round trip
// (through the encoded bytes too) for one and for kMaxImpulses impulses with the epoch and the
// frame, refusal of plans the message cannot carry, and rejection of malformed messages on the
// receiving side with the executor's reason (docs/GUIDANCE_NODE.md PLAN-IF-1).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "evade/guidance_lcm/burn_plan_convert.hpp"

namespace {

using evade::BurnPlan;
using evade::PlanObjective;
using evade::PlanSource;
using evade::Vec3;
using evade::guidance_lcm::burn_plan_message_error;
using evade::guidance_lcm::from_lcm;
using evade::guidance_lcm::to_lcm;

std::uint64_t bits(double x) {
  std::uint64_t b = 0;
  std::memcpy(&b, &x, sizeof b);
  return b;
}
void expect_same(const Vec3& a, const Vec3& b, const std::string& what) {
  for (int i = 0; i < 3; ++i) EXPECT_EQ(bits(a(i)), bits(b(i))) << what << "(" << i << ")";
}

// Every field, bit for bit, including the unused impulse slots.
void expect_identical(const BurnPlan& a, const BurnPlan& b) {
  EXPECT_EQ(a.plan_id, b.plan_id);
  EXPECT_EQ(a.n_impulses, b.n_impulses);
  for (int k = 0; k < BurnPlan::kMaxImpulses; ++k) {
    const auto& x = a.impulses[static_cast<std::size_t>(k)];
    const auto& y = b.impulses[static_cast<std::size_t>(k)];
    EXPECT_EQ(bits(x.t_s), bits(y.t_s)) << "impulse " << k;
    expect_same(x.dv_rsw_mps, y.dv_rsw_mps, "dv_rsw_mps of impulse " + std::to_string(k));
    EXPECT_EQ(x.dv_eci_valid, y.dv_eci_valid) << "impulse " << k;
    expect_same(x.dv_eci_mps, y.dv_eci_mps, "dv_eci_mps of impulse " + std::to_string(k));
  }
  EXPECT_EQ(a.source, b.source);
  EXPECT_EQ(a.observability.valid, b.observability.valid);
  EXPECT_EQ(bits(a.observability.eps_rad), bits(b.observability.eps_rad));
  EXPECT_EQ(bits(a.observability.theta_rad), bits(b.observability.theta_rad));
  EXPECT_EQ(a.observability.objective, b.observability.objective);
  EXPECT_EQ(bits(a.observability.objective_value), bits(b.observability.objective_value));
  EXPECT_EQ(a.observability.evaluations, b.observability.evaluations);
}

// Numbers that a lossy copy (float, text, rounding) would change.
BurnPlan observability_plan() {
  BurnPlan p;
  p.plan_id = 17;
  p.n_impulses = 1;
  p.impulses[0].t_s = 0.1;
  p.impulses[0].dv_rsw_mps = Vec3(-0.0, 2.9999999999999996, std::nextafter(1e-3, 1.0));
  p.source = static_cast<int>(PlanSource::kObservability);
  p.observability.valid = true;
  p.observability.eps_rad = -4.9406564584124654e-324;  // smallest subnormal
  p.observability.theta_rad = -3.2453001234567891;
  p.observability.objective = static_cast<int>(PlanObjective::kEstimation);
  p.observability.objective_value = 1.0 / 3.0;
  p.observability.evaluations = 2801;
  return p;
}

BurnPlan formation_plan_with_eci() {
  BurnPlan p;
  p.plan_id = -5;
  p.n_impulses = 1;
  p.impulses[0].t_s = 5400.000000000001;
  p.impulses[0].dv_rsw_mps = Vec3(0.0, 0.012345678901234567, 0.0);
  p.impulses[0].dv_eci_valid = true;
  p.impulses[0].dv_eci_mps = Vec3(-0.007, 0.0099999999999999985, 1e-17);
  p.source = static_cast<int>(PlanSource::kFormation);
  return p;
}

evade::evade_burn_plan_t through_bytes(const evade::evade_burn_plan_t& m) {
  std::vector<std::uint8_t> buf(static_cast<std::size_t>(m.getEncodedSize()));
  EXPECT_EQ(m.encode(buf.data(), 0, static_cast<int>(buf.size())), static_cast<int>(buf.size()));
  evade::evade_burn_plan_t out{};
  EXPECT_EQ(out.decode(buf.data(), 0, static_cast<int>(buf.size())), static_cast<int>(buf.size()));
  return out;
}

std::string refusal(const BurnPlan& p) {
  evade::evade_burn_plan_t m{};
  m.seq = -7;  // sentinel: a refused plan leaves the message as it was
  try {
    to_lcm(p, 1, 2, &m);
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(m.seq, -7) << "message changed by a refused plan";
    return e.what();
  }
  return "";
}

TEST(BurnPlanConvert, ObservabilityPlanRoundTripsBitExact) {
  const BurnPlan p = observability_plan();
  evade::evade_burn_plan_t m{};
  to_lcm(p, 1700000000123456LL, p.plan_id, &m);
  EXPECT_EQ(m.utime, 1700000000123456LL);
  EXPECT_EQ(m.seq, 17);
  BurnPlan q;
  q.impulses[3].t_s = 99.0;  // from_lcm overwrites every field
  ASSERT_TRUE(from_lcm(through_bytes(m), &q));
  expect_identical(p, q);
}

TEST(BurnPlanConvert, PlanWithEciDeltaVFromAnotherPlannerRoundTripsBitExact) {
  const BurnPlan p = formation_plan_with_eci();
  evade::evade_burn_plan_t m{};
  to_lcm(p, 0, p.plan_id, &m);
  BurnPlan q;
  ASSERT_TRUE(from_lcm(through_bytes(m), &q));
  expect_identical(p, q);
  EXPECT_FALSE(q.observability.valid);
}

TEST(BurnPlanConvert, MessageFieldsFollowThePlanAndTheMessageCodes) {
  static_assert(static_cast<int>(PlanSource::kObservability) ==
                evade::evade_burn_plan_t::SOURCE_OBSERVABILITY_ISRES);
  static_assert(static_cast<int>(PlanObjective::kPaper) ==
                evade::evade_burn_plan_t::OBJECTIVE_PAPER);
  static_assert(static_cast<int>(PlanObjective::kLosChange) ==
                evade::evade_burn_plan_t::OBJECTIVE_LOS_CHANGE);
  static_assert(static_cast<int>(PlanObjective::kEstimation) ==
                evade::evade_burn_plan_t::OBJECTIVE_ESTIMATION);
  BurnPlan p = observability_plan();
  p.impulses[0].dv_eci_mps = Vec3(1.0, 2.0, 3.0);  // not valid: must not be sent
  evade::evade_burn_plan_t m{};
  to_lcm(p, 5, 6, &m);
  EXPECT_EQ(m.source, evade::evade_burn_plan_t::SOURCE_OBSERVABILITY_ISRES);
  EXPECT_EQ(m.objective, evade::evade_burn_plan_t::OBJECTIVE_ESTIMATION);
  EXPECT_EQ(m.impulse_dv_eci_valid[0], 0);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(m.impulse_dv_eci_mps[0][i], 0.0);
  EXPECT_EQ(bits(m.impulse_dv_mps[0]), bits(p.impulses[0].dv_rsw_mps.norm()));
  EXPECT_EQ(bits(m.impulse_t_s[0]), bits(0.1));
  EXPECT_EQ(m.n_impulses, 1);
  EXPECT_EQ(m.epoch_utime, 5);  // default: the publication time
  EXPECT_EQ(m.frame, evade::evade_burn_plan_t::FRAME_RSW);
  for (int k = 1; k < BurnPlan::kMaxImpulses; ++k) EXPECT_EQ(m.impulse_t_s[k], 0.0) << k;
}

TEST(BurnPlanConvert, FullPlanWithEpochAndFrameRoundTripsBitExact) {
  BurnPlan p = formation_plan_with_eci();
  p.n_impulses = BurnPlan::kMaxImpulses;
  for (int k = 1; k < BurnPlan::kMaxImpulses; ++k) {
    auto& b = p.impulses[static_cast<std::size_t>(k)];
    b.t_s = 5400.000000000001 + 1000.0 * k + 1.0 / 3.0;
    b.dv_rsw_mps = Vec3(1e-3 * k, -0.1 / k, std::nextafter(0.0, 1.0));
    b.dv_eci_valid = true;
    b.dv_eci_mps = Vec3(-1e-3 * k, 0.1 / k, -std::nextafter(0.0, 1.0));
  }
  evade::evade_burn_plan_t m{};
  to_lcm(p, 7, p.plan_id, 1700000000000001LL, evade::guidance::PlanFrame::kEci, &m);
  evade::guidance::UplinkedPlan q;
  ASSERT_TRUE(from_lcm(through_bytes(m), &q));
  expect_identical(p, q.plan);
  EXPECT_EQ(q.epoch_utime_us, 1700000000000001LL);
  EXPECT_EQ(q.frame, evade::guidance::PlanFrame::kEci);
  // ECI frame without an ECI Δv cannot be sent.
  p.impulses[3].dv_eci_valid = false;
  EXPECT_THROW(to_lcm(p, 7, 1, 0, evade::guidance::PlanFrame::kEci, &m), std::invalid_argument);
}

TEST(BurnPlanConvert, NoOrTooManyImpulsesAreRefused) {
  for (int n : {0, -1, BurnPlan::kMaxImpulses + 1}) {
    BurnPlan p = observability_plan();
    p.n_impulses = n;
    const std::string why = refusal(p);
    EXPECT_NE(why.find("BurnPlan.n_impulses = " + std::to_string(n)), std::string::npos) << why;
    EXPECT_NE(why.find("[1, 8]"), std::string::npos) << why;
  }
}

TEST(BurnPlanConvert, InconsistentOrNonFinitePlanIsRefusedNamingTheField) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  BurnPlan p = observability_plan();
  p.observability.valid = false;
  EXPECT_NE(refusal(p).find("BurnPlan.observability.valid"), std::string::npos);
  p = formation_plan_with_eci();
  p.observability.valid = true;
  EXPECT_NE(refusal(p).find("BurnPlan.observability.valid"), std::string::npos);
  p = formation_plan_with_eci();
  p.source = 2;
  EXPECT_NE(refusal(p).find("BurnPlan.source = 2"), std::string::npos);
  p = observability_plan();
  p.observability.objective = 7;
  EXPECT_NE(refusal(p).find("BurnPlan.observability.objective = 7"), std::string::npos);
  p = observability_plan();
  p.observability.theta_rad = nan;
  EXPECT_NE(refusal(p).find("BurnPlan.observability.theta_rad"), std::string::npos);
  p = observability_plan();
  p.impulses[0].t_s = nan;
  EXPECT_NE(refusal(p).find("BurnPlan.impulses[0].t_s"), std::string::npos);
  p = formation_plan_with_eci();
  p.impulses[0].dv_eci_mps.y() = std::numeric_limits<double>::infinity();
  EXPECT_NE(refusal(p).find("BurnPlan.impulses[0].dv_eci_mps"), std::string::npos);
}

TEST(BurnPlanConvert, MalformedMessagesAreRejectedNamingTheField) {
  evade::evade_burn_plan_t good{};
  to_lcm(observability_plan(), 1, 2, &good);
  ASSERT_EQ(burn_plan_message_error(good), nullptr);
  using R = evade::guidance::PlanReject;
  ASSERT_EQ(evade::guidance_lcm::burn_plan_message_reject(good), R::kNone);
  struct Case {
    void (*spoil)(evade::evade_burn_plan_t*);
    const char* field;
    R reject;
  };
  const Case cases[] = {
      {[](evade::evade_burn_plan_t* m) { m->theta_rad = std::nan(""); }, "theta_rad", R::kNotFinite},
      {[](evade::evade_burn_plan_t* m) { m->impulse_dv_rsw_mps[0][2] = INFINITY; },
       "impulse_dv_rsw_mps", R::kNotFinite},
      {[](evade::evade_burn_plan_t* m) { m->impulse_t_s[0] = NAN; }, "impulse_t_s", R::kNotFinite},
      {[](evade::evade_burn_plan_t* m) { m->impulse_dv_eci_valid[0] = 2; }, "impulse_dv_eci_valid",
       R::kMalformed},
      {[](evade::evade_burn_plan_t* m) { m->source = 9; }, "source", R::kMalformed},
      {[](evade::evade_burn_plan_t* m) { m->objective = 5; }, "objective", R::kMalformed},
      {[](evade::evade_burn_plan_t* m) { m->evaluations = -1; }, "evaluations", R::kMalformed},
      {[](evade::evade_burn_plan_t* m) { m->n_impulses = 0; }, "n_impulses", R::kImpulseCount},
      {[](evade::evade_burn_plan_t* m) { m->n_impulses = 9; }, "n_impulses", R::kImpulseCount},
      {[](evade::evade_burn_plan_t* m) { m->frame = 2; }, "frame", R::kUnknownFrame},
      {[](evade::evade_burn_plan_t* m) { m->frame = 1; }, "frame", R::kUnknownFrame},
      {[](evade::evade_burn_plan_t* m) { m->frame = -1; }, "frame", R::kUnknownFrame},
      {[](evade::evade_burn_plan_t* m) { m->eps_rad = -INFINITY; }, "eps_rad", R::kNotFinite},
      {[](evade::evade_burn_plan_t* m) { m->objective_value = NAN; }, "objective_value",
       R::kNotFinite},
      {[](evade::evade_burn_plan_t* m) { m->objective = -1; }, "objective", R::kMalformed},
      {[](evade::evade_burn_plan_t* m) { m->source = -1; }, "source", R::kMalformed},
      {[](evade::evade_burn_plan_t* m) { m->source = 2; }, "source", R::kMalformed},
      {[](evade::evade_burn_plan_t* m) { m->impulse_dv_mps[0] = NAN; }, "impulse_dv_mps",
       R::kNotFinite},
      {[](evade::evade_burn_plan_t* m) {
         m->impulse_dv_eci_valid[0] = 1;  // the ECI delta-v is then read and must be finite
         m->impulse_dv_eci_mps[0][1] = NAN;
       },
       "impulse_dv_eci_mps", R::kNotFinite},
      {[](evade::evade_burn_plan_t* m) { m->impulse_dv_eci_valid[0] = -1; },
       "impulse_dv_eci_valid", R::kMalformed},
  };
  for (const Case& c : cases) {
    evade::evade_burn_plan_t m = good;
    c.spoil(&m);
    const char* why = burn_plan_message_error(m);
    ASSERT_NE(why, nullptr) << c.field;
    EXPECT_NE(std::string(why).find(c.field), std::string::npos) << why;
    EXPECT_EQ(evade::guidance_lcm::burn_plan_message_reject(m), c.reject) << c.field;
    BurnPlan out;
    out.plan_id = 123;
    EXPECT_FALSE(from_lcm(m, &out)) << c.field;
    EXPECT_EQ(out.plan_id, 123) << "rejected message changed the plan";
    evade::guidance::UplinkedPlan up;
    up.epoch_utime_us = 5;
    EXPECT_FALSE(from_lcm(m, &up)) << c.field;
    EXPECT_EQ(up.epoch_utime_us, 5) << "rejected message changed the uplinked plan";
  }
}

// The receiving side knows every planner code; the observability block (objective, angles,
// objective value, evaluations) is checked, and carried, only for source 4.
TEST(BurnPlanConvert, EveryPlannerCodeIsAcceptedAndOnlyObservabilityCarriesItsBlock) {
  evade::evade_burn_plan_t good{};
  to_lcm(observability_plan(), 1, 2, &good);
  for (int code : {0, 1, 3, 5}) {
    evade::evade_burn_plan_t m = good;
    m.source = static_cast<std::int16_t>(code);
    m.objective = 99;            // ignored: no observability block for this source
    m.objective_value = NAN;
    EXPECT_EQ(burn_plan_message_error(m), nullptr) << "source " << code;
    BurnPlan out;
    ASSERT_TRUE(from_lcm(m, &out)) << "source " << code;
    EXPECT_EQ(out.source, code);
    EXPECT_FALSE(out.observability.valid) << "source " << code;
  }
  BurnPlan out;
  ASSERT_TRUE(from_lcm(good, &out));
  EXPECT_TRUE(out.observability.valid);
  EXPECT_EQ(out.observability.evaluations, 2801);
}

// The sending side refuses what the receiving side would reject, naming the field.
TEST(BurnPlanConvert, EveryPlanFieldCheckRefusesItsBadValueNamingTheField) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  BurnPlan p = observability_plan();
  p.observability.evaluations = -1;
  EXPECT_NE(refusal(p).find("BurnPlan.observability.evaluations = -1: must be >= 0"),
            std::string::npos);
  p = observability_plan();
  p.observability.eps_rad = inf;
  EXPECT_NE(refusal(p).find("BurnPlan.observability.eps_rad = inf"), std::string::npos);
  p = observability_plan();
  p.observability.objective_value = nan;
  EXPECT_NE(refusal(p).find("BurnPlan.observability.objective_value"), std::string::npos);
  p = observability_plan();
  p.observability.objective = -1;
  EXPECT_NE(refusal(p).find("BurnPlan.observability.objective = -1"), std::string::npos);
  p = observability_plan();
  p.impulses[0].dv_rsw_mps.x() = nan;
  EXPECT_NE(refusal(p).find("BurnPlan.impulses[0].dv_rsw_mps"), std::string::npos);
  for (int code : {0, 1, 3, 5}) {  // every planner code without the block is sent
    p = formation_plan_with_eci();
    p.source = code;
    EXPECT_EQ(refusal(p), "") << "source " << code;
  }
  // A frame code that is neither RSW nor ECI.
  evade::evade_burn_plan_t m{};
  m.seq = -7;
  try {
    to_lcm(formation_plan_with_eci(), 1, 2, 3, static_cast<evade::guidance::PlanFrame>(2), &m);
    ADD_FAILURE() << "frame 2 was sent";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("BurnPlan.frame = 2: allowed 0 RSW, 1 ECI"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(m.seq, -7) << "message changed by a refused plan";
}

TEST(BurnPlanConvert, CorruptBytesAreRejectedByDecode) {
  evade::evade_burn_plan_t m{};
  std::vector<uint8_t> buf(static_cast<std::size_t>(m.getEncodedSize()));
  ASSERT_EQ(m.encode(buf.data(), 0, static_cast<int>(buf.size())), static_cast<int>(buf.size()));
  buf[0] ^= 0xFF;  // breaks the fingerprint
  evade::evade_burn_plan_t out{};
  EXPECT_LT(out.decode(buf.data(), 0, static_cast<int>(buf.size())), 0);
  EXPECT_LT(out.decode(buf.data(), 0, 4), 0);  // truncated
}

}  // namespace
