// sim::run_plan_simulation (plan_run.hpp): the truth samples a run records on request (each
// at the first cycle start at or after its time, the rest at the end) are the unforced truth
// when nothing thrusts, and bad sample times are refused naming the field.
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "evade/sim/plan_run.hpp"

namespace evade::sim {
namespace {

class Idle final : public GuidanceEndpoint {
 public:
  guidance::ThrustCommand exchange(std::int64_t, const guidance::NavState&,
                                   const guidance::AnglesMeasurement*) override {
    return {};
  }
};

PlanRunConfig leo_pair() {
  PlanRunConfig cfg;
  const double r0 = kEarthDefault.re_m + 500e3;
  const double v0 = std::sqrt(kEarthDefault.mu_m3ps2 / r0);
  cfg.satellite0 = {Vec3(r0, 0.0, 0.0), Vec3(0.0, v0, 0.0)};
  cfg.other0 = {Vec3(r0, 1000.0, 0.0), Vec3(0.0, v0, 1.0)};
  cfg.rate_hz = 10.0;
  cfg.duration_s = 20.0;
  return cfg;
}

TEST(PlanRun, SamplesAreTheTruthAtTheCycleStartAtOrAfterEachRequestedTime) {
  PlanRunConfig cfg = leo_pair();
  cfg.sample_t_s = {0.0, 5.55, 12.0, 20.0};
  Idle idle;
  const PlanRunResult r = run_plan_simulation(cfg, idle);
  ASSERT_EQ(r.samples.size(), 4u);
  const double expect_t[] = {0.0, 5.6, 12.0, 20.0};
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_NEAR(r.samples[k].t_s, expect_t[k], 1e-9);
    StateEci sat, oth;
    if (expect_t[k] > 0.0) {
      propagate_unforced(cfg, r.samples[k].t_s, &sat, &oth);
    } else {
      sat = cfg.satellite0;
      oth = cfg.other0;
    }
    // Cycle-by-cycle DOP853 vs one adaptive run, both at the tight tolerance (1e-13).
    EXPECT_LT((r.samples[k].satellite.r_eci_m - sat.r_eci_m).norm(), 1e-6) << k;
    EXPECT_LT((r.samples[k].other.r_eci_m - oth.r_eci_m).norm(), 1e-6) << k;
  }
  EXPECT_TRUE(r.burns.empty());
}

TEST(PlanRun, BadSampleTimesAreRefusedNamingTheField) {
  Idle idle;
  for (const auto& times : {std::vector<double>{5.0, 4.0}, std::vector<double>{21.0},
                            std::vector<double>{-1.0},
                            std::vector<double>{std::numeric_limits<double>::quiet_NaN()}}) {
    PlanRunConfig cfg = leo_pair();
    cfg.sample_t_s = times;
    try {
      (void)run_plan_simulation(cfg, idle);
      ADD_FAILURE() << "accepted sample times starting " << times.front();
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("sample_t_s["), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace evade::sim
