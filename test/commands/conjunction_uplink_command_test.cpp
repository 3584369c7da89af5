// `evade conjunction`'s event from a CDM (docs/AUTONOMY.md AUT-9): the states and covariances
// are evade plan cam's reading of the same CDM, TCA and the window are the CDM's TCA as Unix
// time (checked against `date -u +%s`), the id and version come from the designators and the
// CREATION_DATE, and an event the node would refuse is an error naming the flag or keyword.
#include <cstdint>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "evade/commands/conjunction_uplink_command.hpp"
#include "evade/commands/plan_cam_command.hpp"

namespace evade::commands {
namespace {

std::string cdm_text() {
  std::ifstream in(EVADE_TEST_CDM_DIR "/cam-example.cdm");
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

// `date -u -d 2026-11-24T12:00:00Z +%s`: the CDM's TCA.
constexpr std::int64_t kTcaUs = 1795521600LL * 1000000;
constexpr std::int64_t kDayUs = 86400LL * 1000000;

ConjunctionUplink read(const config::Scenario& sc, std::int64_t now_us = kTcaUs - kDayUs) {
  return read_conjunction_uplink(sc, cdm_text(), "cam-example.cdm", 20.0, now_us);
}

config::Scenario with(const char* key, double v) {
  config::Scenario sc = config::Scenario::empty("test");
  sc.set_value(ParamValue{std::string("uplink.") + key, v});
  return sc;
}

std::string error_of(const config::Scenario& sc, std::int64_t now_us = kTcaUs - kDayUs) {
  try {
    (void)read(sc, now_us);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(ConjunctionUplinkCommand, TheEventIsPlanCamsReadingOfTheCdmAtItsTca) {
  const ConjunctionUplink u = read(config::Scenario::empty("test"));
  const PlanCamRequest p =
      read_plan_cam_request_cdm(config::Scenario::empty("test"), cdm_text(), "cam", 20.0);
  const autonomy::ConjunctionEvent& e = u.event;
  EXPECT_EQ(e.tca_us, kTcaUs);
  EXPECT_EQ(e.x1_eci, p.conjunction.obj[0].state.stacked());
  EXPECT_EQ(e.x2_eci, p.conjunction.obj[1].state.stacked());
  // Symmetrized: within rounding of plan cam's R P R^T, and exactly symmetric.
  EXPECT_LE((e.cov1_eci - p.conjunction.obj[0].cov_eci).cwiseAbs().maxCoeff(),
            1e-12 * p.conjunction.obj[0].cov_eci.cwiseAbs().maxCoeff());
  EXPECT_EQ(e.cov1_eci, e.cov1_eci.transpose());
  EXPECT_EQ(e.cov2_eci, e.cov2_eci.transpose());
  EXPECT_EQ(e.hbr_m, 20.0);
  EXPECT_EQ(e.pc_red, 1e-4);
  EXPECT_EQ(e.pc_target, 1e-5);
  EXPECT_EQ(e.burn_start_us, kTcaUs - 21600LL * 1000000);
  EXPECT_EQ(e.burn_end_us, kTcaUs - 600LL * 1000000);
  EXPECT_EQ(e.veto_deadline_us, kTcaUs - 7200LL * 1000000);
  EXPECT_EQ(autonomy::check_event(e, kTcaUs - kDayUs), autonomy::EventProblem::kNone);
}

TEST(ConjunctionUplinkCommand, IdFromTheDesignatorsAndVersionFromTheCreationDate) {
  const ConjunctionUplink u = read(config::Scenario::empty("test"));
  EXPECT_EQ(u.object1, "90001");
  EXPECT_EQ(u.object2, "90002");
  // FNV-1a 32 of "90001/90002" (Fowler, Noll, Vo), masked to 31 bits, computed independently.
  EXPECT_EQ(u.event.event_id, 925351081);
  EXPECT_EQ(conjunction_event_id("90002", "90001") == u.event.event_id, false);
  // 2026-11-23T12:00:00Z - 2000-01-01T00:00:00Z (`date -u +%s` of both).
  EXPECT_EQ(u.event.version, 848750400);
  const ConjunctionUplink given = read(with("event_id", 12));
  EXPECT_EQ(given.event.event_id, 12);
  EXPECT_EQ(read(with("event_version", 3)).event.version, 3);
}

TEST(ConjunctionUplinkCommand, TheSettingsMoveTheThresholdsWindowAndDeadline) {
  EXPECT_EQ(read(with("pc_red", 1e-3)).event.pc_red, 1e-3);
  const ConjunctionUplink w = read(with("window_open_before_tca_s", 5400.0));
  EXPECT_EQ(w.event.burn_start_us, kTcaUs - 5400LL * 1000000);
  EXPECT_EQ(read(with("veto_deadline_before_tca_s", 900.0)).event.veto_deadline_us,
            kTcaUs - 900LL * 1000000);
}

TEST(ConjunctionUplinkCommand, AnEventTheNodeWouldRefuseIsAnErrorNamingItsFlagOrKeyword) {
  const std::string target = error_of(with("pc_target", 1e-3));
  EXPECT_NE(target.find("--pc-target"), std::string::npos) << target;
  EXPECT_NE(target.find("--pc-red"), std::string::npos) << target;
  const std::string window = error_of(with("window_open_before_tca_s", 300.0));
  EXPECT_NE(window.find("--window-open-before-tca-s"), std::string::npos) << window;
  const std::string deadline = error_of(with("veto_deadline_before_tca_s", 60.0));
  EXPECT_NE(deadline.find("--veto-deadline-before-tca-s"), std::string::npos) << deadline;
  const std::string past = error_of(config::Scenario::empty("test"), kTcaUs + 1);
  EXPECT_NE(past.find("tca_not_ahead"), std::string::npos) << past;
  EXPECT_NE(past.find("2026-11-24T12:00:00.000"), std::string::npos) << past;
  const std::string far = error_of(config::Scenario::empty("test"), kTcaUs - 8 * kDayUs);
  EXPECT_NE(far.find("tca_not_ahead"), std::string::npos) << far;
  EXPECT_THROW((void)read(with("pc_red", 0.0)), config::ConfigError);
}

TEST(ConjunctionUplinkCommand, TheJsonCarriesTheEventAsSent) {
  const ConjunctionUplink u = read(config::Scenario::empty("test"));
  const nlohmann::json j = to_json(u);
  EXPECT_EQ(j["event_id"], u.event.event_id);
  EXPECT_EQ(j["tca"]["utime"], kTcaUs);
  EXPECT_EQ(j["object1"]["r_eci_m"][0], u.event.x1_eci(0));
  EXPECT_EQ(j["object2"]["cov_eci"][5][5], u.event.cov2_eci(5, 5));
  EXPECT_EQ(j["veto_deadline"]["utime"], u.event.veto_deadline_us);
}

}  // namespace
}  // namespace evade::commands
