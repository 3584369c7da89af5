// `evade plan cam` as a library call (assessment/plan_cam_command.hpp): run_plan_cam on the
// shipped example (scenarios/cam-example.yaml, Pc 1.9e-3, burn 17000 s before TCA for
// Pc <= 1e-4: verified), the same conjunction as a CDM (the burn's UTC is the CDM's TCA
// 2026-11-24 12:00:00 UTC minus 17000 s = 07:16:40 UTC = 1795504600 s since the Unix epoch),
// the JSON keys the CLI prints, the text with the burn's UTC and Δv frames, and the
// lead-time trade space; and the recommended Pc deciding the burn (Alfano 2009 cases 7 and 8,
// where the usage checks escalate to 3D-Nc and 2D and 3D-Nc straddle pc_max).
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

#include "evade/commands/plan_cam_command.hpp"

namespace evade::assessment {
namespace {

using namespace evade::commands;
using namespace evade::cam;

std::string file_text(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

PlanCamRequest example_request() {
  PlanCamRequest req =
      read_plan_cam_request(config::Scenario::load(EVADE_TEST_SCENARIO_DIR "/cam-example.yaml"));
  req.cam.lead_s = 17000.0;
  req.cam.pc_max = 1e-4;
  return req;
}

TEST(PlanCamCommand, ShippedExampleIsVerified) {
  const PlanCamResult r = run_plan_cam(example_request());
  ASSERT_TRUE(r.plan);
  EXPECT_NEAR(r.plan->before.pc, 1.9178e-3, 1e-6);
  EXPECT_TRUE(r.plan->verified_ok);
  EXPECT_LE(r.plan->verified.pc, 1e-4);
  EXPECT_NEAR(r.plan->dv_mps, 0.0254, 1e-4);
  EXPECT_FALSE(r.burn_utc_j2000_s);  // a scenario has no UTC
  const nlohmann::json j = to_json(r);
  for (const char* k : {"source", "maneuver_needed", "lead_s", "pc_target", "dv_mps", "dv_rtn_mps",
                        "dv_eci_mps", "burn_from_epoch_s", "tca_from_epoch_s", "before", "predicted",
                        "predicted_first_linearization", "verified", "verified_ok",
                        "relinearizations", "last_change_mps", "search", "nlopt_result",
                        "primary_at_burn", "frames"})
    EXPECT_TRUE(j.contains(k)) << k;
  EXPECT_FALSE(j.contains("burn_utc"));
  EXPECT_EQ(j["dv_rtn_mps"].size(), 3u);
}

TEST(PlanCamCommand, CdmGivesTheBurnUtc) {
  PlanCamRequest req = read_plan_cam_request_cdm(
      config::Scenario::empty("test"), file_text(EVADE_TEST_CDM_DIR "/cam-example.cdm"), "cam", 15.0);
  req.cam.lead_s = 17000.0;
  req.cam.pc_max = 1e-4;
  const PlanCamResult r = run_plan_cam(req);
  ASSERT_TRUE(r.burn_unix_utime_us);
  EXPECT_EQ(*r.burn_unix_utime_us, 1795504600000000);
  EXPECT_EQ(to_json(r)["burn_utc"], "2026-11-24 07:16:40.000000000");
  const std::string t = to_text(r);
  EXPECT_NE(t.find("2026-11-24 07:16:40.000000000 UTC"), std::string::npos) << t;
  EXPECT_NE(t.find("dv RTN ["), std::string::npos) << t;
  EXPECT_NE(t.find("dv ECI ["), std::string::npos) << t;
  EXPECT_NE(t.find("m/s  (J2000 axes)"), std::string::npos) << t;
}

TEST(PlanCamCommand, SweepHasOneRowPerLead) {
  PlanCamRequest req = example_request();
  req.sweep = CamLeadSweep{3000.0, 9000.0, 2};
  const PlanCamResult r = run_plan_cam(req);
  EXPECT_FALSE(r.plan);
  ASSERT_EQ(r.sweep.size(), 2u);
  EXPECT_EQ(r.sweep[1].lead_s, 9000.0);
  const nlohmann::json j = to_json(r);
  EXPECT_EQ(j["rows"].size(), 2u);
  for (const char* k : {"source", "pc_max", "min_miss_m", "along_track_only"})
    EXPECT_TRUE(j.contains(k)) << k;
  EXPECT_EQ(to_text(r).rfind("lead_s,dv_mps,dv_r_mps", 0), 0u);
  req.sweep = CamLeadSweep{0.0, 9000.0, 2};  // lead 0 is not a burn before TCA
  EXPECT_THROW((void)run_plan_cam(req), std::invalid_argument);
  req.sweep = CamLeadSweep{3000.0, 9000.0, 0};
  EXPECT_THROW((void)run_plan_cam(req), std::invalid_argument);
}

// An Alfano 2009 case (test/data/alfano2009) with its published HBR and 3D-Nc window (case 7:
// 10 m, +-1419 s; case 8: 4 m, +-10135 s) and a burn lead_s before TCA.
PlanCamRequest alfano_request(const char* name, double hbr_m, double window_s, double lead_s,
                              double pc_max) {
  PlanCamRequest req = read_plan_cam_request_cdm(
      config::Scenario::empty("test"),
      file_text(std::string(EVADE_TEST_ALFANO_DIR "/") + name), name, hbr_m);
  req.assess_config.window_s = window_s;
  req.cam.lead_s = lead_s;
  req.cam.pc_max = pc_max;
  return req;
}

// Case 7: 2D 1.5815e-4 < pc_max = 1.6e-4 < 3D-Nc 1.6184e-4 (the recommended one): the 2D Pc
// alone would say no burn is needed; the recommended Pc says one is, and it is verified by
// the recommended Pc at the new TCA.
TEST(PlanCamCommand, RecommendedPcAboveTwoDimensionalAsksForABurn) {
  const PlanCamResult r = run_plan_cam(alfano_request("AlfanoTestCase07.cdm", 10.0, 1419.0, 1800.0, 1.6e-4));
  ASSERT_TRUE(r.plan);
  const CamPlan& p = *r.plan;
  EXPECT_LT(p.before.pc, 1.6e-4);
  EXPECT_EQ(p.before_recommended.method, "3d_nc");
  EXPECT_NEAR(p.before_recommended.pc, 1.618412e-4, 1e-9);  // docs/VALIDATION.md, case 7
  EXPECT_TRUE(p.maneuver_needed);
  EXPECT_GT(p.dv_mps, 0.0);
  EXPECT_TRUE(p.verified_ok);
  EXPECT_EQ(p.verified_recommended.method, "3d_nc");
  EXPECT_LE(p.verified_recommended.pc, 1.6e-4);
}

// Case 7 at pc_max = 1e-4: the 2D plan alone ends with 3D-Nc above pc_max (verified_ok false
// with no correction); the corrected 2D target brings the recommended Pc under it.
TEST(PlanCamCommand, TargetCorrectionMeetsTheRecommendedPc) {
  PlanCamRequest req = alfano_request("AlfanoTestCase07.cdm", 10.0, 1419.0, 1800.0, 1e-4);
  req.cam_config.max_target_corrections = 0;
  const CamPlan uncorrected = *run_plan_cam(req).plan;
  EXPECT_LE(uncorrected.verified.pc, 1e-4);                 // the 2D model met its target
  EXPECT_GT(uncorrected.verified_recommended.pc, 1e-4);     // the recommended Pc did not
  EXPECT_FALSE(uncorrected.verified_ok);
  req.cam_config = CamConfig{};
  const PlanCamResult r = run_plan_cam(req);
  const CamPlan& p = *r.plan;
  EXPECT_TRUE(p.verified_ok);
  EXPECT_GE(p.target_corrections, 1);
  EXPECT_LE(p.verified_recommended.pc, 1e-4);
  EXPECT_LT(p.pc_target_2d, p.pc_target);
  EXPECT_GT(p.dv_mps, uncorrected.dv_mps);
  const nlohmann::json j = to_json(r);
  for (const char* k : {"before_recommended", "verified_recommended", "target_corrections",
                        "pc_target_2d"})
    EXPECT_TRUE(j.contains(k)) << k;
  EXPECT_EQ(j["verified_recommended"]["method"], "3d_nc");
  EXPECT_NE(to_text(r).find("verified recommended Pc: "), std::string::npos);
}

// Case 8: 3D-Nc 0.03525 < pc_max = 0.036 < 2D 0.03694: the recommended Pc says no burn.
TEST(PlanCamCommand, RecommendedPcBelowTwoDimensionalNeedsNoBurn) {
  const PlanCamResult r = run_plan_cam(alfano_request("AlfanoTestCase08.cdm", 4.0, 10135.0, 1800.0, 0.036));
  const CamPlan& p = *r.plan;
  EXPECT_GT(p.before.pc, 0.036);
  EXPECT_EQ(p.before_recommended.method, "3d_nc");
  EXPECT_LT(p.before_recommended.pc, 0.036);
  EXPECT_FALSE(p.maneuver_needed);
  EXPECT_TRUE(p.verified_ok);
  EXPECT_EQ(p.dv_mps, 0.0);
}

}  // namespace
}  // namespace evade::assessment
