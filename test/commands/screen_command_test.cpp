// `evade screen` as library calls (screen_command.hpp): paper 002's seed2 screened by both
// methods finds the 14 head-on collisions of the 12-hour case (Wang Xiaoyu 2006, Table 2),
// the JSON has the keys the CLI prints, the CDMs of a population carry a Pc each, the SGP4
// catalog path names a decaying element set, the text gives UTC TCAs to the millisecond and
// explains the paper's COLLISION flag; the brute-force reference screening (refactored in
// parts) agrees with the robust screener on a small population.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "evade/config/scenario.hpp"
#include "evade/conjunction/population.hpp"
#include "evade/conjunction/reference_screen.hpp"
#include "evade/commands/screen_command.hpp"
#include "evade/sgp4/tle_reader.hpp"

namespace evade::conjunction {
namespace {

using namespace evade::commands;

ScreenObjectsRequest seed2_request(const std::string& method) {
  const config::Scenario sc = config::Scenario::load("seed2");
  ScreenObjectsSource src;
  src.method = method;
  ScreenObjectsRequest req = read_screen_objects_request(sc, src);
  req.threads = 1;
  return req;
}

void expect_keys(const nlohmann::json& j, const std::vector<std::string>& keys) {
  for (const auto& k : keys) EXPECT_TRUE(j.contains(k)) << "missing key " << k;
}

TEST(ScreenCommand, RobustSeed2FindsFourteenCollisions) {
  const ScreenObjectsResult r = run_screen_objects(seed2_request("robust"));
  ASSERT_EQ(r.events.size(), 14u);
  for (const auto& c : r.events) {
    EXPECT_TRUE(c.collision);
    EXPECT_LT(c.miss_m, 1e-2);
    EXPECT_NEAR(c.rel_speed_mps, 14707.393, 1e-3);
  }
  EXPECT_EQ(r.objects_source.find("seed2") != std::string::npos, true);
  const nlohmann::json j = to_json(r);
  expect_keys(j, {"command", "method", "objects_source", "objects", "epoch_utc", "span_s",
                  "scenario", "steps", "stats", "wall_time_s", "events"});
  EXPECT_FALSE(j.contains("trace"));
  EXPECT_FALSE(j.contains("cdm"));
  expect_keys(j["stats"], {"grid_steps", "pairs_checked", "candidates", "narrow_phase_intervals",
                           "root_solves", "pairs_after_apogee_perigee", "unproven_leaves",
                           "all_pairs", "threads", "ranks", "grid_step_s"});
  expect_keys(j["events"][0], {"i", "j", "name_i", "name_j", "tca_s", "tca_utc", "miss_m",
                               "rel_speed_mps", "collision", "warning"});
  EXPECT_EQ(j["events"][0]["tca_utc"], "1999-10-01 00:26:14.492420307");
}

TEST(ScreenCommand, PaperSeed2FlagsFourteenCollisionsWithTrace) {
  ScreenObjectsRequest req = seed2_request("paper");
  req.trace = true;
  const ScreenObjectsResult r = run_screen_objects(req);
  EXPECT_EQ(r.events.size(), 14u);
  EXPECT_EQ(r.steps, 1790);
  EXPECT_EQ(r.trace.size(), 1791u);  // t = 0 and every step
  const nlohmann::json j = to_json(r);
  expect_keys(j, {"command", "method", "steps", "trace", "events"});
  EXPECT_FALSE(j.contains("stats"));
  expect_keys(j["trace"][0], {"t_s", "utc", "step_s", "i", "j", "distance_m",
                              "radial_speed_mps", "collision", "warning"});
}

TEST(ScreenCommand, TextHasUtcMillisecondsAndExplainsCollision) {
  const std::string text = to_text(run_screen_objects(seed2_request("robust")));
  EXPECT_NE(text.find("TCA 1999-10-01 00:26:14.492 UTC"), std::string::npos) << text;
  EXPECT_EQ(text.find("14.492420307"), std::string::npos);
  EXPECT_NE(text.find("COLLISION: miss <= R_c"), std::string::npos);
  EXPECT_NE(text.find("not a probability"), std::string::npos);
}

TEST(ScreenCommand, UtcTextRoundsToTheMillisecond) {
  EXPECT_EQ(utc_text_ms(0.0), "2000-01-01 12:00:00.000 UTC");
  EXPECT_EQ(utc_text_ms(59.9996), "2000-01-01 12:01:00.000 UTC");
  EXPECT_EQ(utc_text_ms(-0.0004), "2000-01-01 12:00:00.000 UTC");
  EXPECT_EQ(utc_text_ms(43199.9995), "2000-01-02 00:00:00.000 UTC");
  EXPECT_EQ(utc_text_ms(1.2344), "2000-01-01 12:00:01.234 UTC");
  EXPECT_EQ(utc_text_ms(1.2346), "2000-01-01 12:00:01.235 UTC");
}

TEST(ScreenCommand, InapplicableOptionsAreRefusedNamingTheFlag) {
  ScreenObjectsRequest req = seed2_request("robust");
  req.trace = true;
  EXPECT_THROW(
      {
        try {
          req.validate();
        } catch (const std::invalid_argument& e) {
          EXPECT_NE(std::string(e.what()).find("--trace: only with --method paper"), std::string::npos);
          throw;
        }
      },
      std::invalid_argument);
  ScreenObjectsRequest paper = seed2_request("paper");
  paper.cdm.dir = "cdm";
  EXPECT_THROW(paper.validate(), std::invalid_argument);
  ScreenObjectsRequest hbr = seed2_request("robust");
  hbr.cdm.dir = "cdm";
  hbr.cdm.hbr_m = 5.0;  // without a covariance: no Pc to use it for
  EXPECT_THROW(hbr.validate(), std::invalid_argument);
}

TEST(ScreenCommand, PopulationCdmsCarryAPcPerEvent) {
  const config::Scenario sc = config::Scenario::load("seed2");
  ScreenObjectsSource src;
  src.population = 100;
  src.seed = 3;
  ScreenObjectsRequest req = read_screen_objects_request(sc, src);
  req.threads = 1;
  req.cdm.dir = "cdm";
  req.cdm.cov_rtn_sigma_text = "100,300,50";
  req.cdm.cov_rtn_sigma_m = {100.0, 300.0, 50.0};
  req.cdm.creation_utc_j2000_s = 0.0;
  const ScreenObjectsResult r = run_screen_objects(req);
  ASSERT_FALSE(r.events.empty());
  ASSERT_TRUE(r.cdm.has_value());
  ASSERT_EQ(r.cdm->files.size(), r.events.size());
  for (const auto& f : r.cdm->files) {
    ASSERT_TRUE(f.pc.has_value());
    EXPECT_GE(*f.pc, 0.0);
    EXPECT_LE(*f.pc, 1.0);
    EXPECT_NE(f.text.find("COLLISION_PROBABILITY"), std::string::npos);
    EXPECT_NE(f.text.find("REF_FRAME"), std::string::npos);
  }
  const nlohmann::json j = to_json(r);
  expect_keys(j["cdm"], {"dir", "format", "count", "covariance", "files"});
  expect_keys(j["cdm"]["files"][0], {"file", "message_id", "pc"});
  EXPECT_EQ(j["cdm"]["covariance"], "assumed RTN sigmas 100,300,50 m");
  EXPECT_NE(to_text(r).find("  Pc "), std::string::npos);
}

TEST(ScreenCommand, AssumedCovarianceIsDiagonalAndChecked) {
  commands::ScreenCdmOptions o;
  EXPECT_FALSE(commands::assumed_rtn_covariance(o).has_value());
  o.cov_rtn_sigma_text = "100,300,50";
  o.cov_rtn_sigma_m = {100.0, 300.0, 50.0};
  const auto c = commands::assumed_rtn_covariance(o);
  ASSERT_TRUE(c.has_value());
  EXPECT_EQ((*c)(0, 0), 1e4);
  EXPECT_EQ((*c)(1, 1), 9e4);
  EXPECT_EQ((*c)(2, 2), 2500.0);
  EXPECT_EQ((*c)(3, 3), 0.0);
  EXPECT_EQ((*c)(0, 1), 0.0);
  o.cov_rtn_sigma_m = {100.0, -1.0, 50.0};
  EXPECT_THROW((void)commands::assumed_rtn_covariance(o), std::invalid_argument);
}

TEST(ScreenCommand, CatalogNamesTheDecayingElementSet) {
  const std::string tle =
      "0 SYN LEO 0001\n"
      "1 90000U 87085J   26318.54353962 -.00000006  00000-0  43151-4 0   776\n"
      "2 90000  98.2063 184.8671 0011853 294.9300 245.3170 15.03200139114506\n"
      "0 SYN LEO 0002\n"
      "1 90001U 73105L   26318.99555320  .00000004  00000-0  62956-4 0  4816\n"
      "2 90001  52.2195 171.6366 0019025 138.4493  10.9780 15.09938705952025\n"
      "0 FALLING\n"
      "1 99002U 26001A   26320.50000000  .00100000  00000-0  50000-0 0  9993\n"
      "2 99002  51.6000 100.0000 0010000  90.0000 270.0000 16.40000000    16\n";
  ScreenCatalogRequest req;
  req.catalog = sgp4::read_tle(tle, "test.tle");
  req.source = "test.tle";
  req.threads = 1;
  std::string diagnostics;
  req.diagnostic = [&diagnostics](const std::string& s) { diagnostics += s; };
  const ScreenCatalogResult r = run_screen_catalog(req);
  EXPECT_EQ(r.objects, 2);
  ASSERT_EQ(r.rejections.size(), 1u);
  EXPECT_EQ(r.rejections[0].rfind("NORAD 99002 (FALLING): SGP4 error 1", 0), 0u) << r.rejections[0];
  EXPECT_NE(diagnostics.find("rejected: NORAD 99002"), std::string::npos);
  EXPECT_EQ(r.frame, "TEME");
  const nlohmann::json j = to_json(r);
  expect_keys(j, {"command", "motion", "frame", "source", "start_utc", "span_s", "threshold_m",
                  "objects", "bad_entries", "rejected", "rejections", "stats",
                  "motion_setup_wall_s", "screen_wall_s", "events"});
  EXPECT_FALSE(j.contains("primary"));
  EXPECT_NE(to_text(r).find(" UTC over 86400 s"), std::string::npos) << to_text(r);
  req.span_s = -5.0;
  EXPECT_THROW((void)run_screen_catalog(req), std::invalid_argument);
}

TEST(ReferenceScreen, AgreesWithRobustOnASmallPopulation) {
  PopulationOptions pop;
  pop.count = 120;
  pop.seed = 5;
  pop.span_s = 7200.0;
  pop.coorbital_fraction = 0.1;
  pop.crossing_fraction = 0.1;
  const auto objects = synthetic_population(pop);
  ScreenOptions opt;
  opt.threshold_m = 5000.0;
  opt.threads = 1;
  const ScreenResult robust = screen_robust(objects, pop.span_s, opt);
  const ScreenResult ref = screen_reference(objects, pop.span_s, 1.0, opt);
  ASSERT_FALSE(ref.events.empty());
  ASSERT_EQ(ref.events.size(), robust.events.size());
  for (std::size_t k = 0; k < ref.events.size(); ++k) {
    EXPECT_EQ(ref.events[k].i, robust.events[k].i);
    EXPECT_EQ(ref.events[k].j, robust.events[k].j);
    EXPECT_NEAR(ref.events[k].tca_s, robust.events[k].tca_s, 1e-3);
    EXPECT_NEAR(ref.events[k].miss_m, robust.events[k].miss_m, 1e-3);
  }
}

}  // namespace
}  // namespace evade::conjunction
