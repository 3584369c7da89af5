// The 2D Pc as the node computes it (docs/AUTONOMY.md AUT-4): the same value, bit for bit, as
// the ground's pc_2d (one implementation: the ground's call runs the workspace version) on
// Chan's encounter-plane cases, encounters of the Alfano 2009 set and the most elongated
// ellipse of the test suite; Chan's published case 01; every bad input reported as a status and
// never thrown; the panel count bounded by the workspace; nothing allocated, by the Pc nor by the
// whole 2D assessment (encounter_2d.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "evade/assessment/encounter_2d.hpp"
#include "evade/assessment/pc_2d.hpp"
#include "support/counting_new.hpp"

namespace evade::assessment {
namespace {

// Chan's cases, encounters seen in the Alfano 2009 set (tiny sigmas against the radius) and the
// most elongated ellipse of the test suite (sigmas 1.9e5 m and 1.6e8 m: it took 20,000 panels
// before the workspace bound, for a value whose error estimate was already 1e-10 of it).
struct Case {
  PrincipalEncounter e;
  double hbr_m;
};
const Case kCases[] = {
    {{0.0, 10.0, 25.0, 50.0}, 5.0},
    {{10.0, 0.0, 25.0, 75.0}, 5.0},
    {{1000.0, 200.0, 300.0, 3000.0}, 20.0},
    {{15.0, 0.0, 0.140585, 0.140585}, 10.0},
    {{-5.00006, 0.706003, 0.00389927, 0.190712}, 15.0},
    {{-2.77953, 6.09853, 190872.0, 1.62213e8}, 10.0},
};

TEST(Pc2dFlight, WorkspaceVersionIsTheGroundsValueBitForBit) {
  Pc2dWorkspace ws;
  for (const Case& c : kCases) {
    Pc2dResult flight;
    ASSERT_EQ(pc_2d(c.e, c.hbr_m, 1e-10, &ws, &flight), Pc2dStatus::kOk);
    const Pc2dResult ground = pc_2d(c.e, c.hbr_m, 1e-10);
    EXPECT_EQ(flight.pc, ground.pc);
    EXPECT_EQ(flight.abs_error, ground.abs_error);
    EXPECT_EQ(flight.panels, ground.panels);
    EXPECT_LE(flight.panels, Pc2dWorkspace::kMaxPanels);
  }
}

// Chan 2008's case 01 (miss 10 m, sigmas 25 and 50 m, radius 5 m): 9.742e-3 as published, to
// the 4 digits given (the ground's test of it is PcValidation's Chan01).
TEST(Pc2dFlight, ReproducesChansPublishedCase01) {
  Pc2dWorkspace ws;
  Pc2dResult r;
  ASSERT_EQ(pc_2d({0.0, 10.0, 25.0, 50.0}, 5.0, 1e-10, &ws, &r), Pc2dStatus::kOk);
  EXPECT_NEAR(r.pc, 9.742e-3, 0.5e-6);
}

TEST(Pc2dFlight, BadInputIsAStatusNeverAThrow) {
  Pc2dWorkspace ws;
  Pc2dResult r;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(pc_2d({nan, 0.0, 1.0, 1.0}, 5.0, 1e-8, &ws, &r), Pc2dStatus::kNotFinite);
  EXPECT_EQ(r.pc, 0.0);
  EXPECT_EQ(pc_2d({0.0, 0.0, 0.0, 1.0}, 5.0, 1e-8, &ws, &r), Pc2dStatus::kBadSigma);
  EXPECT_EQ(pc_2d({0.0, 0.0, 1.0, 1.0}, -5.0, 1e-8, &ws, &r), Pc2dStatus::kBadHbr);
  EXPECT_EQ(pc_2d({0.0, 0.0, 1.0, 1.0}, 5.0, 0.0, &ws, &r), Pc2dStatus::kBadTolerance);
  EXPECT_THROW(pc_2d(PrincipalEncounter{0.0, 0.0, 0.0, 1.0}, 5.0), std::invalid_argument);
}

TEST(Pc2dFlight, TheWorkspaceVersionAllocatesNothing) {
  Pc2dWorkspace ws;
  Pc2dResult r;
  const long before = g_news.load();
  for (const Case& c : kCases) (void)pc_2d(c.e, c.hbr_m, 1e-10, &ws, &r);
  EXPECT_EQ(g_news.load() - before, 0);
}

TEST(Encounter2d, AllocatesNothing) {
  Pc2dWorkspace ws;
  Encounter2d e;
  const StateEci s1{Vec3(7e6, 0, 0), Vec3(0, 7546, 0)};
  const StateEci s2{Vec3(7e6, 100, 0), Vec3(0, 0, 7546)};
  Mat6 c = Mat6::Identity() * 1e4;
  c(0, 0) = -1.0;  // an NPD covariance: the repair path too
  const long before = g_news.load();
  ASSERT_EQ(assess_encounter_2d(s1, c, s2, Mat6::Identity() * 4e4, 10.0, Encounter2dConfig{},
                                kEarthDefault, &ws, &e),
            Encounter2dStatus::kOk);
  EXPECT_EQ(g_news.load() - before, 0);
  EXPECT_TRUE(e.npd[0]);
}

}  // namespace
}  // namespace evade::assessment
