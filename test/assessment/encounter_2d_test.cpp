// The 2D assessment of an encounter as the node runs it (docs/AUTONOMY.md AUT-4) is evade
// assess's, bit for bit: on the eleven Alfano 2009 CDMs and the shipped CDMs, read as
// `evade assess --cdm` reads them and assessed at the CDM's TCA (assessment.tca_search_s = 0,
// as the node assesses the uplinked states), assess_encounter_2d gives the same Pc, the same
// CARA 2D usage figures and failed checks and the same short-term verdict as assess() and
// usage_2d(); bad covariances and a zero relative speed are statuses. (That it allocates
// nothing is in pc_2d_flight_test.cpp, the executable's one replacement of operator new.)
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "evade/assessment/assess.hpp"
#include "evade/assessment/encounter_2d.hpp"
#include "evade/assessment/pc_method_choice.hpp"
#include "evade/ccsds/cdm_formats.hpp"
#include "evade/commands/conjunction_input.hpp"
#include "evade/core/erfc_inverse.hpp"

namespace evade::assessment {
namespace {

std::vector<std::string> cdm_files() {
  std::vector<std::string> f;
  for (int i : {1, 2, 3, 4, 5, 6, 7, 8, 9, 11}) {
    char name[64];
    std::snprintf(name, sizeof(name), "/AlfanoTestCase%02d.cdm", i);
    f.push_back(std::string(EVADE_TEST_ALFANO_DIR) + name);
  }
  f.push_back(std::string(EVADE_TEST_CDM_DIR) + "/alfano-2009-case01.cdm");
  f.push_back(std::string(EVADE_TEST_CDM_DIR) + "/cam-example.cdm");
  return f;
}

ConjunctionInput read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return commands::conjunction_from_cdm(ccsds::read_cdm_text(ss.str()), 20.0, kEarthDefault);
}

Encounter2dConfig flight_config(const AssessConfig& c) {
  Encounter2dConfig f;
  f.pc_rel_tol = c.pc_rel_tol;
  f.short_term_max_period_fraction = c.short_term_max_period_fraction;
  f.short_term_max_vel_sigma_ratio = c.short_term_max_vel_sigma_ratio;
  f.conj_bound_factor = std::sqrt(2.0) * erfc_inverse(c.conj_duration_gamma);
  f.pc2d_extended_cutoff = c.pc2d_extended_cutoff;
  f.pc2d_offset_cutoff = c.pc2d_offset_cutoff;
  return f;
}

TEST(Encounter2d, IsEvadeAssessBitForBitOnTheAlfanoAndShippedCdms) {
  AssessConfig cfg;
  cfg.tca_search_s = 0.0;
  Pc2dWorkspace ws;
  int cases = 0;
  for (const std::string& path : cdm_files()) {
    const ConjunctionInput in = read(path);
    if (!in.obj[0].has_velocity_cov || !in.obj[1].has_velocity_cov) continue;
    const Assessment a = assess(in, cfg);
    Encounter2d e;
    ASSERT_EQ(assess_encounter_2d(in.obj[0].state, in.obj[0].cov_eci, in.obj[1].state,
                                  in.obj[1].cov_eci, in.hbr_m, flight_config(cfg), in.earth, &ws,
                                  &e),
              Encounter2dStatus::kOk) << path;
    EXPECT_EQ(e.pc.pc, pc_of(a.plane_pc, PcMethod::k2d)) << path;
    const std::vector<UsageFlag> flags = usage_2d(a, in.hbr_m, cfg, in.earth);
    ASSERT_EQ(flags.size(), 4U);
    EXPECT_EQ(e.usage.extended, flags[0].value) << path;
    EXPECT_EQ(e.usage.offset, flags[1].value) << path;
    EXPECT_EQ((e.failed & kUsageExtended) != 0, flags[0].violated) << path;
    EXPECT_EQ((e.failed & kUsageOffset) != 0, flags[1].violated) << path;
    EXPECT_EQ((e.failed & kUsageNpd) != 0, flags[2].violated) << path;
    EXPECT_EQ((e.failed & kUsageShortTerm) != 0, flags[3].violated) << path;
    EXPECT_EQ(e.short_term.valid, a.short_term.valid) << path;
    EXPECT_EQ(e.short_term.encounter_time_s, a.short_term.encounter_time_s) << path;
    ++cases;
  }
  EXPECT_GE(cases, 10) << "the CDMs carry 6x6 covariances";
}

TEST(Encounter2d, BadCovariancesAndNoRelativeSpeedAreStatuses) {
  Pc2dWorkspace ws;
  Encounter2d e;
  const StateEci s1{Vec3(7e6, 0, 0), Vec3(0, 7546, 0)};
  const StateEci s2{Vec3(7e6, 100, 0), Vec3(0, 0, 7546)};
  const Mat6 good = Mat6::Identity() * 1e4;
  Mat6 asym = good;
  asym(0, 1) = 5.0;
  Mat6 nan = good;
  nan(2, 2) = std::nan("");
  const Encounter2dConfig cfg;
  EXPECT_EQ(assess_encounter_2d(s1, asym, s2, good, 10.0, cfg, kEarthDefault, &ws, &e),
            Encounter2dStatus::kBadCovariance);
  EXPECT_EQ(assess_encounter_2d(s1, good, s2, nan, 10.0, cfg, kEarthDefault, &ws, &e),
            Encounter2dStatus::kBadCovariance);
  EXPECT_EQ(assess_encounter_2d(s1, -good, s2, -good, 10.0, cfg, kEarthDefault, &ws, &e),
            Encounter2dStatus::kBadCovariance);
  EXPECT_EQ(assess_encounter_2d(s1, good, {s2.r_eci_m, s1.v_eci_mps}, good, 10.0, cfg,
                                kEarthDefault, &ws, &e),
            Encounter2dStatus::kZeroSpeed);
  EXPECT_EQ(assess_encounter_2d(s1, good, s2, good, -1.0, cfg, kEarthDefault, &ws, &e),
            Encounter2dStatus::kBadPc);
}

}  // namespace
}  // namespace evade::assessment
