// An uplinked conjunction is checked field by field before anything uses it (docs/AUTONOMY.md
// AUT-1): ids, finiteness, ranges, symmetric covariances, the window and the veto deadline in
// order before TCA, TCA ahead but not more than 7 days.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>

#include "evade/autonomy/conjunction_event.hpp"

namespace evade::autonomy {
namespace {

constexpr std::int64_t kNow = 1'000'000'000'000;

ConjunctionEvent good() {
  ConjunctionEvent e;
  e.event_id = 7;
  e.version = 1;
  e.tca_us = kNow + 3'600'000'000;
  e.x1_eci << 7.0e6, 0.0, 0.0, 0.0, 7546.0, 0.0;
  e.x2_eci << 7.0e6, 100.0, 0.0, 0.0, 0.0, 7546.0;
  e.cov1_eci = Mat6::Identity() * 1e4;
  e.cov2_eci = Mat6::Identity() * 4e4;
  e.hbr_m = 20.0;
  e.pc_red = 1e-4;
  e.pc_target = 1e-6;
  e.burn_start_us = kNow + 600'000'000;
  e.burn_end_us = kNow + 3'000'000'000;
  e.veto_deadline_us = kNow + 500'000'000;
  return e;
}

TEST(ConjunctionEvent, AGoodEventPasses) { EXPECT_EQ(check_event(good(), kNow), EventProblem::kNone); }

TEST(ConjunctionEvent, EachBadFieldIsNamed) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct Case {
    void (*mutate)(ConjunctionEvent&, double);
    EventProblem want;
  } cases[] = {
      {[](ConjunctionEvent& e, double) { e.event_id = 0; }, EventProblem::kBadId},
      {[](ConjunctionEvent& e, double) { e.version = -1; }, EventProblem::kBadId},
      {[](ConjunctionEvent& e, double n) { e.x1_eci[3] = n; }, EventProblem::kNotFinite},
      {[](ConjunctionEvent& e, double n) { e.cov2_eci(5, 5) = n; }, EventProblem::kNotFinite},
      {[](ConjunctionEvent& e, double n) { e.pc_red = n; }, EventProblem::kNotFinite},
      {[](ConjunctionEvent& e, double) { e.hbr_m = 0.0; }, EventProblem::kOutOfRange},
      {[](ConjunctionEvent& e, double) { e.hbr_m = 1001.0; }, EventProblem::kOutOfRange},
      {[](ConjunctionEvent& e, double) { e.pc_target = 1e-8; }, EventProblem::kOutOfRange},
      {[](ConjunctionEvent& e, double) { e.pc_target = 1e-3; }, EventProblem::kOutOfRange},
      {[](ConjunctionEvent& e, double) { e.x2_eci[0] = 2e9; }, EventProblem::kOutOfRange},
      {[](ConjunctionEvent& e, double) { e.x1_eci.head<3>().setZero(); }, EventProblem::kOutOfRange},
      {[](ConjunctionEvent& e, double) { e.cov1_eci(0, 3) = 1.0; }, EventProblem::kAsymmetric},
      {[](ConjunctionEvent& e, double) { e.burn_end_us = e.burn_start_us; }, EventProblem::kBadWindow},
      {[](ConjunctionEvent& e, double) { e.burn_end_us = e.tca_us + 1; }, EventProblem::kBadWindow},
      {[](ConjunctionEvent& e, double) { e.veto_deadline_us = e.burn_end_us + 1; }, EventProblem::kBadWindow},
      {[](ConjunctionEvent& e, double) {
         e.tca_us = kNow; e.burn_end_us = kNow; e.burn_start_us = kNow - 10; e.veto_deadline_us = kNow - 10;
       }, EventProblem::kTcaNotAhead},
      {[](ConjunctionEvent& e, double) { e.tca_us = kNow + EventLimits::kMaxLeadUs + 1; }, EventProblem::kTcaNotAhead},
  };
  for (const Case& c : cases) {
    ConjunctionEvent e = good();
    c.mutate(e, nan);
    EXPECT_EQ(check_event(e, kNow), c.want) << event_problem_name(c.want);
  }
  ConjunctionEvent edge = good();
  edge.pc_red = edge.pc_target = EventLimits::kMinPc;  // configurable down to 1e-7
  EXPECT_EQ(check_event(edge, kNow), EventProblem::kNone);
}

}  // namespace
}  // namespace evade::autonomy
