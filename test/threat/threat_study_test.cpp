// Tests of the transfer-time study (paper 001 sec. 2.1 eq. 3, Fig. 4) and of the whole
// threat-area study (sec. 3–4): the numbers `evade plan threat-area --scenario seed1 --json`
// printed before its computations moved into the library (same inputs, same values).
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "evade/config/scenario.hpp"
#include "evade/commands/threat_scenario.hpp"
#include "evade/threat/threat_study.hpp"
#include "evade/threat/transfer_study.hpp"
#include "seed1_geometry.hpp"

namespace evade::threat {
namespace {

using testing::seed1_geometry;
using testing::seed1_options;

struct CliTransferRow {
  double dt_s, cost2, cost3, cost4, primer_lb, primer_max, t0_bound;
};

// `--sweep-transfer 1400,2200,3000,4200,5400` on seed1.
const CliTransferRow kCliRows[] = {
    {1400.0, 152.27828378708006, 152.27828378708006, 152.27828378708006, 152.11927565760806,
     1.0010452858704764, 171.72171621291994},
    {2200.0, 83.48078242728009, 83.48078242728009, 83.48078242728009, 83.2889006185698,
     1.0023038100789567, 240.51921757271992},
    {3000.0, 48.40676782921879, 48.40676782921878, 48.40676782921879, 48.207534630991915,
     1.0041328227994217, 275.5932321707812},
    {4200.0, 22.02894533948446, 22.02894533948446, 22.02894533948446, 21.840110155095257,
     1.0086462560421265, 301.97105466051556},
    {5400.0, 12.11553029549085, 12.11553029549085, 12.11553029549085, 11.90589349476158,
     1.0176078175755148, 311.8844697045092},
};

TEST(TransferStudy, Seed1RowsAreTheCliNumbers) {
  for (const CliTransferRow& c : kCliRows) {
    const TransferStudyRow r = study_transfer_time(seed1_geometry(), seed1_options(), c.dt_s);
    EXPECT_EQ(r.dt_transfer_s, c.dt_s);
    EXPECT_DOUBLE_EQ(r.cost_t0_mps[0], c.cost2) << c.dt_s;
    EXPECT_DOUBLE_EQ(r.cost_t0_mps[1], c.cost3) << c.dt_s;
    EXPECT_DOUBLE_EQ(r.cost_t0_mps[2], c.cost4) << c.dt_s;
    EXPECT_DOUBLE_EQ(r.primer_lower_bound_t0_mps, c.primer_lb) << c.dt_s;
    EXPECT_DOUBLE_EQ(r.primer_max_t0, c.primer_max) << c.dt_s;
    EXPECT_DOUBLE_EQ(r.t0_bound_mps, c.t0_bound) << c.dt_s;
    EXPECT_DOUBLE_EQ(r.j_t0_mps + r.t0_bound_mps, 324.0);
    EXPECT_FALSE(r.elimination.has_value());
  }
  EXPECT_THROW(study_transfer_time(seed1_geometry(), seed1_options(), 0.0),
               std::invalid_argument);
}

TEST(ThreatStudy, Seed1DefaultRunIsTheCliNumbers) {
  const ThreatScenario in = commands::read_threat_scenario(config::Scenario::load("seed1"));
  const ThreatStudy s = run_threat_study(in, {});
  EXPECT_DOUBLE_EQ(in.geometry.n_radps, 0.0011407009380488985);
  EXPECT_DOUBLE_EQ(s.period_s, 5508.1793111581055);
  EXPECT_DOUBLE_EQ(s.chaser_cost_t0_mps, 83.48078242728009);
  EXPECT_DOUBLE_EQ(s.two_impulse_cost_t0_mps, 83.48078242728009);
  EXPECT_DOUBLE_EQ(s.t0_bound_mps, 240.51921757271992);
  const EvasionResult& r = s.evasion;
  EXPECT_EQ(r.dv_mps, 20.0);
  EXPECT_DOUBLE_EQ(r.area.arc_s, 2543.14453125);
  EXPECT_DOUBLE_EQ(r.area.arc_deg, 166.21318579723354);
  EXPECT_DOUBLE_EQ(r.area.grid_arc_s, 2545.0);
  ASSERT_EQ(r.area.intervals.size(), 1u);
  EXPECT_EQ(r.area.intervals[0].start_s, 0.0);
  EXPECT_DOUBLE_EQ(r.area.intervals[0].end_s, 2543.14453125);
  EXPECT_DOUBLE_EQ(r.alpha_rad, -0.19025266887535233);
  EXPECT_DOUBLE_EQ(r.theta_rad, -3.1398998981576147);
  EXPECT_DOUBLE_EQ(r.dv_rsw_mps.x(), -3.7821402170203111);
  EXPECT_DOUBLE_EQ(r.dv_rsw_mps.y(), -19.639101562956704);
  EXPECT_DOUBLE_EQ(r.dv_rsw_mps.z(), 0.033244227606708747);
  EXPECT_EQ(r.evaluations, 194);
  EXPECT_EQ(r.counts.two_impulse_accept, 178697);
  EXPECT_EQ(r.counts.bound_reject, 35513);
  EXPECT_EQ(r.counts.sqp_safe, 142);
  EXPECT_EQ(r.counts.total(), 214352);
  // The search's certificate: sweep + BOBYQA, and no direction's arc below (1 − 1e-3) × best.
  EXPECT_EQ(r.certificate.grid_evaluations, 128);
  EXPECT_TRUE(r.certificate.certified);
  EXPECT_GE(r.certificate.lower_bound_arc_s, (1.0 - 1e-3) * r.area.arc_s);
  EXPECT_LE(r.certificate.lower_bound_arc_s, r.area.arc_s);
  EXPECT_FALSE(s.elimination.has_value());
  EXPECT_TRUE(s.sweep_dv.empty());
  EXPECT_TRUE(s.sweep_transfer.empty());
}

// --eliminate --sweep-dv 40,160 --sweep-transfer 3000 with a reduced budget (sweep.step_s=20,
// sweep.edge_tol_s=0.5, evasion.max_evaluations=200, evasion.seed=3, elimination.tol_mps=1).
TEST(ThreatStudy, Seed1EliminationAndSweepsAreTheCliNumbersAndReportProgress) {
  config::Scenario sc = config::Scenario::load("seed1");
  for (const char* a : {"sweep.step_s=20", "sweep.edge_tol_s=0.5", "evasion.max_evaluations=200",
                        "evasion.seed=3", "elimination.tol_mps=1"}) {
    sc.apply_override(a);
  }
  const ThreatScenario in = commands::read_threat_scenario(sc);
  ThreatStudyRequest request;
  request.eliminate = true;
  request.sweep_dv_mps = {40.0, 160.0};
  request.sweep_transfer_s = {3000.0};
  std::vector<std::string> steps;
  ThreatStudyProgress progress;
  progress.optimizing = [&](double, int evals) { steps.push_back("opt" + std::to_string(evals)); };
  progress.eliminating = [&](double) { steps.push_back("elim"); };
  progress.burn_row = [&](const BurnSweepRow&) { steps.push_back("burn"); };
  progress.transfer_row = [&](const TransferStudyRow&) { steps.push_back("transfer"); };
  const ThreatStudy s = run_threat_study(in, request, progress);
  EXPECT_EQ(steps, (std::vector<std::string>{"opt200", "elim", "burn", "burn", "transfer"}));

  EXPECT_DOUBLE_EQ(s.evasion.area.arc_s, 2543.28125);
  EXPECT_DOUBLE_EQ(s.evasion.alpha_rad, -0.19251794600499281);
  ASSERT_TRUE(s.elimination.has_value());
  EXPECT_DOUBLE_EQ(s.elimination->eliminating_dv_mps, 242.3671875);
  EXPECT_DOUBLE_EQ(s.elimination->threatened_dv_mps, 241.734375);
  EXPECT_DOUBLE_EQ(s.elimination->best.alpha_rad, -1.101153345905735);
  EXPECT_DOUBLE_EQ(s.elimination->best.theta_rad, 0.27768424501235373);
  EXPECT_EQ(s.elimination->bisection_steps, 9);
  EXPECT_EQ(s.elimination->evaluations, 1694);
  EXPECT_DOUBLE_EQ(s.eliminating_to_dv_max_ratio, 0.748046875);
  EXPECT_DOUBLE_EQ(s.eliminating_over_t0_bound, 1.0076832526977657);
  ASSERT_EQ(s.sweep_dv.size(), 2u);
  EXPECT_DOUBLE_EQ(s.sweep_dv[0].evasion.area.arc_s, 1358.28125);
  EXPECT_DOUBLE_EQ(s.sweep_dv[0].evasion.alpha_rad, -0.50882371240429991);
  EXPECT_DOUBLE_EQ(s.sweep_dv[1].evasion.area.arc_s, 245.78125);
  EXPECT_DOUBLE_EQ(s.sweep_dv[1].evasion.theta_rad, -3.1415926535897931);
  ASSERT_EQ(s.sweep_transfer.size(), 1u);
  const TransferStudyRow& t = s.sweep_transfer[0];
  EXPECT_DOUBLE_EQ(t.t0_bound_mps, 275.5932321707812);
  ASSERT_TRUE(t.elimination.has_value());
  EXPECT_DOUBLE_EQ(t.elimination->eliminating_dv_mps, 275.90625);
  EXPECT_DOUBLE_EQ(t.elimination->best.alpha_rad, -1.4173278068949102);
  EXPECT_DOUBLE_EQ(t.elimination->best.theta_rad, -2.9452431127404308);
}

}  // namespace
}  // namespace evade::threat
