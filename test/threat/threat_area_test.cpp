// Tests of the potential threat area sweep (paper 001 sec. 2.2, 3.1 eq. 4–7).
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "evade/threat/evasion.hpp"
#include "evade/threat/threat_area.hpp"
#include "seed1_geometry.hpp"

namespace evade::threat {
namespace {

using testing::seed1_geometry;
using testing::seed1_options;

TEST(ThreatArea, WholePeriodThreatensWithoutEvasion) {
  const ThreatAreaSolver s(seed1_geometry(), seed1_options());
  const ThreatArea a = s.evaluate(Vec3::Zero());
  // The chaser parked on the target's orbit is an HCW equilibrium: every departure time sees
  // the same 100 km gap, which costs ≈ 83.5 m/s < 324 m/s.
  ASSERT_EQ(a.intervals.size(), 1u);
  EXPECT_EQ(a.intervals[0].start_s, 0.0);
  EXPECT_DOUBLE_EQ(a.intervals[0].end_s, s.period_s());
  EXPECT_DOUBLE_EQ(a.arc_deg, 360.0);
  EXPECT_EQ(a.threatening_points, a.points);
  // Everything decided by the cheapest test.
  EXPECT_EQ(a.counts.two_impulse_accept, a.counts.total());
}

TEST(ThreatArea, VerdictsAgreeWithFullOptimizationAndEdgesSitOnTheThreshold) {
  ThreatOptions o = seed1_options();
  o.step_s = 20.0;
  o.edge_tol_s = 0.01;
  const ThreatAreaSolver s(seed1_geometry(), o);
  const Vec3 dv = evasion_dv_rsw(150.0, -0.9, -3.0);
  const ThreatArea a = s.evaluate(dv);
  ASSERT_GT(a.arc_s, 0.0);
  ASSERT_LT(a.arc_s, s.period_s());
  EXPECT_GT(a.counts.bound_reject, 0);
  // Every grid verdict agrees with the full-effort optimizer's cost.
  for (long k = 0; k < a.points; ++k) {
    const double t = k * o.step_s;
    bool inside = false;
    for (const auto& iv : a.intervals) inside |= (t >= iv.start_s && t <= iv.end_s);
    const double cost = s.min_cost_plan(t, dv).cost_mps;
    // 0.01 m/s: points with costs this close to ΔV_max can flip with solver tolerance.
    if (std::abs(cost - o.dv_max_mps) > 0.01) {
      EXPECT_EQ(inside, cost <= o.dv_max_mps) << "t=" << t << " cost=" << cost;
    }
  }
  // Refined edges: the cost crosses ΔV_max within the bisection tolerance of each edge.
  for (const auto& iv : a.intervals) {
    for (double e : {iv.start_s, iv.end_s}) {
      if (e <= 0.0 || e >= s.period_s()) continue;
      const double lo = s.min_cost_plan(e - o.edge_tol_s, dv).cost_mps;
      const double hi = s.min_cost_plan(e + o.edge_tol_s, dv).cost_mps;
      EXPECT_LE(std::min(lo, hi), o.dv_max_mps + 1e-6) << "edge " << e;
      EXPECT_GE(std::max(lo, hi), o.dv_max_mps - 1e-6) << "edge " << e;
    }
  }
  // The refined arc and the paper's N_T × step agree within one step per edge.
  EXPECT_NEAR(a.arc_s, a.grid_arc_s, 2.0 * o.step_s * a.intervals.size());
}

TEST(ThreatArea, OneAndTwoThreadsGiveTheSameArea) {
  ThreatOptions o = seed1_options();
  o.step_s = 10.0;
  o.threads = 1;
  const ThreatAreaSolver s1(seed1_geometry(), o);
  o.threads = 2;
  const ThreatAreaSolver s2(seed1_geometry(), o);
  const Vec3 dv = evasion_dv_rsw(100.0, 0.3, 2.0);
  const ThreatArea a1 = s1.evaluate(dv), a2 = s2.evaluate(dv);
  EXPECT_EQ(a1.arc_s, a2.arc_s);
  EXPECT_EQ(a1.threatening_points, a2.threatening_points);
  EXPECT_EQ(a1.counts.total(), a2.counts.total());
}

void expect_rejected(ThreatOptions o, const std::string& field) {
  try {
    const ThreatAreaSolver s(seed1_geometry(), o);
    ADD_FAILURE() << "accepted bad " << field;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
  }
}

TEST(ThreatArea, RejectsBadInputsNamingTheField) {
  ThreatOptions o = seed1_options();
  o.transfer_s = 0.0;
  expect_rejected(o, "dt_transfer_s");
  o = seed1_options();
  o.transfer_s = -100.0;
  expect_rejected(o, "dt_transfer_s");
  o = seed1_options();
  o.dv_max_mps = 0.0;
  expect_rejected(o, "dv_max_mps");
  o = seed1_options();
  o.dv_max_mps = std::nan("");
  expect_rejected(o, "dv_max_mps");
  o = seed1_options();
  o.impulses = 1;
  expect_rejected(o, "impulses");
  o = seed1_options();
  o.step_s = std::nan("");
  expect_rejected(o, "step_s");
  ThreatGeometry g = seed1_geometry();
  g.chaser0_rsw(1) = std::nan("");
  EXPECT_THROW(ThreatAreaSolver(g, seed1_options()), std::invalid_argument);
  const ThreatAreaSolver s(seed1_geometry(), seed1_options());
  EXPECT_THROW(s.evaluate(Vec3(std::nan(""), 0.0, 0.0)), std::invalid_argument);
}

}  // namespace
}  // namespace evade::threat
