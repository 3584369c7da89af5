// The 2D assessment of an encounter as the node runs it (docs/AUTONOMY.md AUT-4) is evade
// assess's, bit for bit: on the eleven Alfano 2009 CDMs and the shipped CDMs, read as
// `evade assess --cdm` reads them and assessed at the CDM's TCA (assessment.tca_search_s = 0,
// as the node assesses the uplinked states), assess_encounter_2d gives the same Pc, the same
// CARA 2D usage figures and failed checks and the same short-term verdict as assess() and
// usage_2d(); the same on 20 LEO conjunctions generated here as CDMs (written as
// `evade screen --cdm-out` writes them, KVN, and read back as `evade assess --cdm` reads them:
// crossing angles from 0.1 mrad to 2.8 rad, so that slow encounters fail the usage checks); bad
// covariances and a zero relative speed are statuses. (That it allocates nothing is in
// pc_2d_flight_test.cpp, the executable's one replacement of operator new.)
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "evade/assessment/assess.hpp"
#include "evade/assessment/covariance.hpp"
#include "evade/assessment/encounter_2d.hpp"
#include "evade/assessment/pc_method_choice.hpp"
#include "evade/ccsds/cdm_formats.hpp"
#include "evade/ccsds/cdm_kvn.hpp"
#include "evade/commands/cdm_from_event.hpp"
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

Encounter2dConfig flight_config(const AssessConfig& c) { return encounter_2d_config(c); }

// The onboard assessment of in against evade assess's (tca_search_s = 0): the same Pc and
// usage figures bit for bit, the same failed checks and short-term verdict. Prints a row;
// *failed (if given): the onboard failed checks (Usage2dBit).
void expect_same_as_assess(const ConjunctionInput& in, const std::string& label, Pc2dWorkspace* ws,
                           std::uint16_t* failed = nullptr) {
  AssessConfig cfg;
  cfg.tca_search_s = 0.0;
  const Assessment a = assess(in, cfg);
  Encounter2d e;
  ASSERT_EQ(assess_encounter_2d(in.obj[0].state, in.obj[0].cov_eci, in.obj[1].state,
                                in.obj[1].cov_eci, in.hbr_m, flight_config(cfg), in.earth, ws, &e),
            Encounter2dStatus::kOk) << label;
  EXPECT_EQ(e.pc.pc, pc_of(a.plane_pc, PcMethod::k2d)) << label;
  const std::vector<UsageFlag> flags = usage_2d(a, in.hbr_m, cfg, in.earth);
  ASSERT_EQ(flags.size(), 4U);
  EXPECT_EQ(e.usage.extended, flags[0].value) << label;
  EXPECT_EQ(e.usage.offset, flags[1].value) << label;
  EXPECT_EQ((e.failed & kUsageExtended) != 0, flags[0].violated) << label;
  EXPECT_EQ((e.failed & kUsageOffset) != 0, flags[1].violated) << label;
  EXPECT_EQ((e.failed & kUsageNpd) != 0, flags[2].violated) << label;
  EXPECT_EQ((e.failed & kUsageShortTerm) != 0, flags[3].violated) << label;
  EXPECT_EQ(e.short_term.valid, a.short_term.valid) << label;
  EXPECT_EQ(e.short_term.encounter_time_s, a.short_term.encounter_time_s) << label;
  if (failed != nullptr) *failed = e.failed;
  std::printf("| %s | %.6e | %.6e | %.3e | %.3e | %s%s%s%s |\n", label.c_str(),
              pc_of(a.plane_pc, PcMethod::k2d), e.pc.pc, e.usage.extended, e.usage.offset,
              flags[0].violated ? "extended " : "", flags[1].violated ? "offset " : "",
              flags[2].violated ? "npd " : "", flags[3].violated ? "short_term" : "");
}

TEST(Encounter2d, IsEvadeAssessBitForBitOnTheAlfanoAndShippedCdms) {
  Pc2dWorkspace ws;
  int cases = 0;
  for (const std::string& path : cdm_files()) {
    const ConjunctionInput in = read(path);
    if (!in.obj[0].has_velocity_cov || !in.obj[1].has_velocity_cov) continue;
    expect_same_as_assess(in, path.substr(path.find_last_of('/') + 1), &ws);
    ++cases;
  }
  EXPECT_GE(cases, 10) << "the CDMs carry 6x6 covariances";
}

// A LEO conjunction as a screening event: a circular primary at 500-900 km, the secondary at
// the same point plus a miss (20-120 m radial, +-60 m across), its velocity the primary's
// turned about the radius by a crossing angle log-uniform in [1e-4, 2.8] rad; RTN sigmas of
// the sizes of the shipped CAM example, each object's scaled by 0.6-1.8.
commands::ScreeningEvent generated_event(std::mt19937_64* rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double mu = kEarthDefault.mu_m3ps2;
  const double r = kEarthDefault.re_m + 500e3 + 400e3 * u(*rng), inc = 0.2 + 1.5 * u(*rng);
  const double cross = 1e-4 * std::pow(28000.0, u(*rng)), v = std::sqrt(mu / r);
  commands::ScreeningEvent ev;
  StateEci& s1 = ev.obj[0].state_eme2000;
  StateEci& s2 = ev.obj[1].state_eme2000;
  s1 = {Vec3(r, 0.0, 0.0), Vec3(0.0, v * std::cos(inc), v * std::sin(inc))};
  s2.v_eci_mps = Vec3(0.0, v * std::cos(inc + cross), v * std::sin(inc + cross));
  const Vec3 n = (s2.v_eci_mps - s1.v_eci_mps).cross(Vec3::UnitX()).normalized();
  s2.r_eci_m = s1.r_eci_m + (20.0 + 100.0 * u(*rng)) * Vec3::UnitX() + (-60.0 + 120.0 * u(*rng)) * n;
  Vec6 sig[2];
  sig[0] << 30.0, 150.0, 20.0, 0.15, 0.03, 0.02;
  sig[1] << 80.0, 600.0, 60.0, 0.6, 0.08, 0.06;
  for (int i = 0; i < 2; ++i) {
    Mat6 c = Mat6::Zero();
    c.diagonal() = ((0.6 + 1.2 * u(*rng)) * sig[i]).cwiseAbs2();
    ev.obj[static_cast<std::size_t>(i)].cov_rtn = c;
    ev.obj[static_cast<std::size_t>(i)].designator = std::to_string(90001 + i);
    ev.obj[static_cast<std::size_t>(i)].name = i == 0 ? "PRIMARY" : "SECONDARY";
  }
  ev.tca_utc_j2000_s = 849600000.0 + 86400.0 * u(*rng);  // 2026-12
  ev.miss_m = (s2.r_eci_m - s1.r_eci_m).norm();
  ev.rel_speed_mps = (s2.v_eci_mps - s1.v_eci_mps).norm();
  return ev;
}

TEST(Encounter2d, IsEvadeAssessBitForBitOnTwentyGeneratedLeoCdms) {
  std::mt19937_64 rng(46);
  Pc2dWorkspace ws;
  int flagged = 0;
  for (int k = 1; k <= 20; ++k) {
    const commands::ScreeningEvent ev = generated_event(&rng);
    commands::EventCdmOptions opt;
    opt.message_id = "generated-" + std::to_string(k);
    opt.creation_utc_j2000_s = ev.tca_utc_j2000_s - 86400.0;
    opt.hbr_m = 10.0 + 10.0 * std::uniform_real_distribution<double>(0.0, 1.0)(rng);
    opt.hbr_source = "generated";
    const std::string kvn = ccsds::write_cdm_kvn(commands::cdm_from_event(ev, opt).cdm);
    const ConjunctionInput in =
        commands::conjunction_from_cdm(ccsds::read_cdm_text(kvn), opt.hbr_m, kEarthDefault);
    ASSERT_TRUE(in.obj[0].has_velocity_cov && in.obj[1].has_velocity_cov) << opt.message_id;
    std::uint16_t failed = 0;
    expect_same_as_assess(in, opt.message_id, &ws, &failed);
    if (failed != 0) ++flagged;
  }
  // The comparison covers both verdicts of the usage checks.
  EXPECT_GT(flagged, 0);
  EXPECT_LT(flagged, 20);
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
