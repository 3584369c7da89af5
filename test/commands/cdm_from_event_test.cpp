// cdm_from_event (CCSDS 508.0-B-1 CDM of one screening event): every mandatory keyword,
// the event's TCA, miss and relative speed to the printed precision after KVN and XML round
// trips, COLLISION_PROBABILITY equal to what `evade assess` recomputes from the written
// message, the object radii recovered from AREA_PC; without covariances: zeros, a COMMENT,
// no Pc, and the assessment refuses the message; bad input refused; deterministic names.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "evade/assessment/assess.hpp"
#include "evade/commands/cdm_from_event.hpp"
#include "evade/ccsds/cdm_kvn.hpp"
#include "evade/ccsds/cdm_xml.hpp"
#include "evade/commands/conjunction_input.hpp"
#include "evade/core/constants.hpp"
#include "evade/core/epoch.hpp"

namespace evade::assessment {
namespace {

using namespace evade::ccsds;

using namespace evade::commands;

// Two LEO objects at their TCA: object 2 crosses object 1's orbit at 60 degrees, 120 m away
// along the direction normal to both velocities (so r.v = 0: the states are at TCA).
ScreeningEvent crossing(bool with_cov) {
  ScreeningEvent ev;
  const double r = 7.0e6, v = std::sqrt(kEarthDefault.mu_m3ps2 / r);
  const Vec3 v1(0.0, v, 0.0), v2(0.0, v * 0.5, v * std::sqrt(0.75));
  const Vec3 dv = v2 - v1;
  const Vec3 miss_dir = Vec3(1.0, 0.0, 0.0).cross(dv).normalized();  // normal to dv
  const Vec3 d = 120.0 * (0.8 * miss_dir + 0.6 * Vec3(1.0, 0.0, 0.0));  // both normal to dv
  ev.obj[0].state_eme2000 = {Vec3(r, 0.0, 0.0), v1};
  ev.obj[1].state_eme2000 = {Vec3(r, 0.0, 0.0) + d, v2};
  ev.obj[0].designator = "90001";
  ev.obj[1].designator = "90002";
  ev.obj[0].name = "OBJ A";
  ev.obj[1].name = "OBJ B";
  ev.obj[0].radius_m = 3.0;
  ev.obj[1].radius_m = 1.5;
  ev.tca_utc_j2000_s = seconds_since_j2000_from_calendar(parse_calendar_utc("2026-11-17T00:49:05.388336"));
  ev.miss_m = d.norm();
  ev.rel_speed_mps = dv.norm();
  ev.screen_start_utc_j2000_s = ev.tca_utc_j2000_s - 3600.0;
  ev.screen_stop_utc_j2000_s = ev.tca_utc_j2000_s + 3600.0;
  ev.screen_threshold_m = 5000.0;
  if (with_cov) {
    Mat6 c = Mat6::Zero();
    c.diagonal() << 100.0 * 100.0, 300.0 * 300.0, 50.0 * 50.0, 0.0, 0.0, 0.0;
    ev.obj[0].cov_rtn = ev.obj[1].cov_rtn = c;
  }
  return ev;
}

EventCdmOptions options() {
  EventCdmOptions o;
  o.hbr_m = 4.5;
  o.creation_utc_j2000_s = 0.0;
  return o;
}

double num(const CdmSection& s, const char* key) { return std::stod(cdm_value(s, key)); }

TEST(CdmFromEvent, KvnAndXmlCarryTheEventAndThePc) {
  const ScreeningEvent ev = crossing(true);
  const EventCdm m = cdm_from_event(ev, options());
  ASSERT_TRUE(m.pc.has_value());
  EXPECT_GT(*m.pc, 1e-6);  // 120 m miss, sigmas 100-300 m: a Pc that matters
  for (const Cdm& c : {read_cdm_kvn(write_cdm_kvn(m.cdm)), read_cdm_xml(write_cdm_xml(m.cdm))}) {
    EXPECT_TRUE(c == m.cdm);
    EXPECT_EQ(cdm_value(c.relative, "TCA"), "2026-11-17T00:49:05.388336");
    // 6 decimals printed: half a unit of the last digit.
    EXPECT_NEAR(num(c.relative, "MISS_DISTANCE"), ev.miss_m, 5e-7);
    EXPECT_NEAR(num(c.relative, "RELATIVE_SPEED"), ev.rel_speed_mps, 5e-7);
    const Vec3 rel(num(c.relative, "RELATIVE_POSITION_R"), num(c.relative, "RELATIVE_POSITION_T"),
                   num(c.relative, "RELATIVE_POSITION_N"));
    EXPECT_NEAR(rel.norm(), ev.miss_m, 1e-6);  // three components, each +-5e-7 m
    EXPECT_EQ(cdm_value(c.object[0].metadata, "REF_FRAME"), "EME2000");
    EXPECT_EQ(cdm_value(c.relative, "COLLISION_PROBABILITY_METHOD"), "FOSTER-1992");
    EXPECT_NEAR(num(c.relative, "COLLISION_PROBABILITY"), *m.pc, 5e-11 * *m.pc);
    // What `evade assess --cdm` does: HBR from AREA_PC (r1 + r2), states and covariances
    // from the message. States are printed to 1 um, which moves the encounter-plane miss by
    // <= 2e-6 m and ln Pc by <= (miss + HBR) / sigma_min^2 x 2e-6 m = 1e-7 (sigma_min 50 m).
    const ConjunctionInput in = conjunction_from_cdm(c, 0.0, kEarthDefault);
    EXPECT_NEAR(in.hbr_m, 4.5, 1e-12);
    const Assessment a = assess(in, AssessConfig{});
    EXPECT_NEAR(assessment::pc_of(a.plane_pc, assessment::PcMethod::k2d), *m.pc, 2e-7 * *m.pc);
    EXPECT_NEAR(a.tca_shift_s, 0.0, 1e-6);
  }
}

TEST(CdmFromEvent, EveryMandatoryKeywordIsWritten) {
  const Cdm c = cdm_from_event(crossing(false), options()).cdm;
  for (const char* k : {"CCSDS_CDM_VERS", "CREATION_DATE", "ORIGINATOR", "MESSAGE_ID"})
    EXPECT_FALSE(cdm_value(c.header, k).empty()) << k;
  for (const char* k : {"TCA", "MISS_DISTANCE"}) EXPECT_FALSE(cdm_value(c.relative, k).empty()) << k;
  for (const auto& o : c.object) {
    for (const char* k : {"OBJECT", "OBJECT_DESIGNATOR", "CATALOG_NAME", "OBJECT_NAME",
                          "INTERNATIONAL_DESIGNATOR", "EPHEMERIS_NAME", "COVARIANCE_METHOD",
                          "MANEUVERABLE", "REF_FRAME"})
      EXPECT_FALSE(cdm_value(o.metadata, k).empty()) << k;
    for (const char* k : {"X", "Y", "Z", "X_DOT", "Y_DOT", "Z_DOT"})
      EXPECT_FALSE(cdm_value(o.state_vector, k).empty()) << k;
    EXPECT_EQ(o.covariance.items.size(), 22u);  // the COMMENT and the 21 terms
  }
  EXPECT_NO_THROW(validate_cdm(c));
}

TEST(CdmFromEvent, UnknownCovarianceWritesZerosCommentAndNoPc) {
  const EventCdm m = cdm_from_event(crossing(false), options());
  EXPECT_FALSE(m.pc.has_value());
  const Cdm& c = m.cdm;
  EXPECT_EQ(c.relative.find("COLLISION_PROBABILITY"), nullptr);
  EXPECT_EQ(c.relative.find("COLLISION_PROBABILITY_METHOD"), nullptr);
  for (const auto& o : c.object) {
    EXPECT_EQ(cdm_value(o.metadata, "COVARIANCE_METHOD"), "DEFAULT");
    EXPECT_EQ(o.covariance.items.front().key, "COMMENT");
    EXPECT_NE(o.covariance.items.front().value.find("covariance not known"), std::string::npos);
    EXPECT_EQ(num(o.covariance, "CR_R"), 0.0);
    EXPECT_EQ(num(o.covariance, "CT_T"), 0.0);
  }
  try {
    (void)conjunction_from_cdm(read_cdm_kvn(write_cdm_kvn(c)), 4.5, kEarthDefault);
    FAIL() << "an all-zero covariance was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("position covariance is all zero (not known)"),
              std::string::npos)
        << e.what();
  }
}

TEST(CdmFromEvent, BadInputIsRefused) {
  EventCdmOptions no_hbr = options();
  no_hbr.hbr_m = 0.0;
  EXPECT_THROW(cdm_from_event(crossing(true), no_hbr), std::invalid_argument);
  ScreeningEvent nan_state = crossing(false);
  nan_state.obj[1].state_eme2000.r_eci_m(0) = std::nan("");
  EXPECT_THROW(cdm_from_event(nan_state, options()), std::invalid_argument);
  ScreeningEvent asym = crossing(true);
  (*asym.obj[0].cov_rtn)(0, 1) = 5.0;
  EXPECT_THROW(cdm_from_event(asym, options()), std::invalid_argument);
  ScreeningEvent no_id = crossing(false);
  no_id.obj[0].designator.clear();
  EXPECT_THROW(cdm_from_event(no_id, options()), std::invalid_argument);
}

TEST(CdmFromEvent, FileStemIsDeterministicAndSafe) {
  ScreeningEvent ev = crossing(false);
  EXPECT_EQ(cdm_event_file_stem(ev), "90001_90002_20261117T004905.388336");
  ev.obj[0].designator = "co 1/a";
  EXPECT_EQ(cdm_event_file_stem(ev), "co_1_a_90002_20261117T004905.388336");
  EXPECT_EQ(cdm_epoch(0.0), "2000-01-01T12:00:00.000000");
}

}  // namespace
}  // namespace evade::assessment
