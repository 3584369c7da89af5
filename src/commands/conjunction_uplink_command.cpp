// The uplinked conjunction from a CDM (include/evade/commands/conjunction_uplink_command.hpp).
#include "evade/commands/conjunction_uplink_command.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "evade/cam/cam_burn_plan.hpp"
#include "evade/ccsds/cdm_formats.hpp"
#include "evade/commands/conjunction_input.hpp"
#include "evade/config/read_params.hpp"
#include "evade/core/epoch.hpp"

namespace evade::commands {
namespace {

using Cfg = ConjunctionUplinkConfig;
constexpr double kWeekS = 7.0 * 86400.0;
constexpr double kIntMax = 2147483647.0;

const Param<Cfg> kConjunctionUplinkRows[] = {
    with_flag(EVADE_PARAM_REAL(Cfg, pc_red, "-", autonomy::EventLimits::kMinPc, 1.0, false,
                               "red threshold: the node plans a burn when the event's Pc is above it"),
              "--pc-red"),
    with_flag(EVADE_PARAM_REAL(Cfg, pc_target, "-", autonomy::EventLimits::kMinPc, 1.0, false,
                               "post-burn target: the burn brings the Pc below it (at most --pc-red)"),
              "--pc-target"),
    with_flag(EVADE_PARAM_REAL(Cfg, window_open_before_tca_s, "s", 0.0, kWeekS, true,
                               "the burn window opens this long before TCA"),
              "--window-open-before-tca-s"),
    with_flag(EVADE_PARAM_REAL(Cfg, window_close_before_tca_s, "s", 0.0, kWeekS, false,
                               "the burn window closes this long before TCA"),
              "--window-close-before-tca-s"),
    with_flag(EVADE_PARAM_REAL(Cfg, veto_deadline_before_tca_s, "s", 0.0, kWeekS, false,
                               "the ground's veto or approval counts until this long before TCA "
                               "(at or before the window's close)"),
              "--veto-deadline-before-tca-s"),
    with_flag(EVADE_PARAM_INT(Cfg, event_id, "-", 0, kIntMax,
                              "the event's id; 0: from the CDM's two OBJECT_DESIGNATORs"),
              "--event-id"),
    with_flag(EVADE_PARAM_INT(Cfg, event_version, "-", 0, kIntMax,
                              "the event's version (a higher one replaces it on the node); 0: "
                              "the CDM's CREATION_DATE in seconds since 2000-01-01"),
              "--event-version"),
};

// The relations between the settings that one range cannot say, named by their flags.
void check_relations(const Cfg& c) {
  if (!(c.pc_target <= c.pc_red))
    throw std::invalid_argument("--pc-target (" + param_value_text(c.pc_target) +
                                ") must be at or below --pc-red (" + param_value_text(c.pc_red) + ")");
  if (!(c.window_open_before_tca_s > c.window_close_before_tca_s))
    throw std::invalid_argument("--window-open-before-tca-s must be greater than "
                                "--window-close-before-tca-s (the window opens before it closes)");
  if (!(c.veto_deadline_before_tca_s >= c.window_close_before_tca_s))
    throw std::invalid_argument("--veto-deadline-before-tca-s must be at least "
                                "--window-close-before-tca-s (the ground decides before the window closes)");
}

double j2000_s_of(const ccsds::CdmSection& s, const char* key) {
  const std::string text = ccsds::cdm_value(s, key);
  if (text.empty()) throw std::invalid_argument(std::string("CDM: no ") + key);
  return seconds_since_j2000_from_calendar(parse_calendar_utc(text));
}

std::int32_t version_of(const Cfg& c, const ccsds::Cdm& cdm) {
  if (c.event_version != 0) return c.event_version;
  const double s = std::floor(j2000_s_of(cdm.header, "CREATION_DATE") + 43200.0);  // from 2000-01-01
  if (!(s >= 1.0 && s <= kIntMax))
    throw std::invalid_argument("CDM: CREATION_DATE is not after 2000-01-01 and before 2068: give "
                                "--event-version");
  return static_cast<std::int32_t>(s);
}

std::int64_t before_tca_us(std::int64_t tca_us, double before_s) {
  return tca_us - static_cast<std::int64_t>(std::llround(before_s * 1e6));
}

// A problem check_event finds, in the words of the flag or keyword that caused it.
void check_as_the_node(const autonomy::ConjunctionEvent& e, std::int64_t now_us,
                       const std::string& tca_utc) {
  const autonomy::EventProblem p = autonomy::check_event(e, now_us);
  switch (p) {
    case autonomy::EventProblem::kNone: return;
    case autonomy::EventProblem::kTcaNotAhead:
      throw std::invalid_argument("CDM: TCA " + tca_utc + " is not ahead of now, or more than 7 "
                                  "days ahead: the node refuses the event (tca_not_ahead)");
    case autonomy::EventProblem::kBadWindow:
      throw std::invalid_argument("the burn window (--window-open-before-tca-s, "
                                  "--window-close-before-tca-s) or --veto-deadline-before-tca-s "
                                  "is not as the node takes it (bad_window)");
    default: break;
  }
  throw std::invalid_argument(std::string("CDM: the node would refuse the event: ") +
                              autonomy::event_problem_name(p) +
                              " (states within 1e9 m and 1e5 m/s, covariances finite, "
                              "--hbr-m in (0, 1000] m)");
}

}  // namespace

ParamTable<ConjunctionUplinkConfig> conjunction_uplink_params() noexcept {
  return make_param_table(kConjunctionUplinkRows);
}

std::int64_t conjunction_event_id(const std::string& object1, const std::string& object2) noexcept {
  std::uint32_t h = 2166136261u;  // FNV-1a, 32 bits
  const std::string key = object1 + "/" + object2;
  for (const char ch : key) {
    h ^= static_cast<unsigned char>(ch);
    h *= 16777619u;
  }
  const std::uint32_t id = h & 0x7fffffffu;
  return id == 0 ? 1 : static_cast<std::int64_t>(id);
}

ConjunctionUplink read_conjunction_uplink(const config::Scenario& sc, const std::string& cdm_text,
                                          const std::string& cdm_name, double hbr_m,
                                          std::int64_t now_us) {
  ConjunctionUplink u;
  config::read_params(sc, "uplink.", conjunction_uplink_params(), &u.config);
  const ccsds::Cdm cdm = ccsds::read_cdm_text(cdm_text);
  const assessment::ConjunctionInput in = conjunction_from_cdm(cdm, hbr_m, config::read_earth(sc));
  sc.check_all_used();
  const Cfg& c = u.config;
  check_relations(c);
  u.source = "cdm " + cdm_name;
  u.message_id = ccsds::cdm_value(cdm.header, "MESSAGE_ID");
  u.creation_date = ccsds::cdm_value(cdm.header, "CREATION_DATE");
  u.tca_utc = ccsds::cdm_value(cdm.relative, "TCA");
  u.object1 = ccsds::cdm_value(cdm.object[0].metadata, "OBJECT_DESIGNATOR");
  u.object2 = ccsds::cdm_value(cdm.object[1].metadata, "OBJECT_DESIGNATOR");
  autonomy::ConjunctionEvent& e = u.event;
  e.event_id = c.event_id != 0 ? c.event_id : conjunction_event_id(u.object1, u.object2);
  e.version = version_of(c, cdm);
  e.tca_us = cam::unix_utime_from_j2000(j2000_s_of(cdm.relative, "TCA"));
  e.x1_eci = in.obj[0].state.stacked();
  e.x2_eci = in.obj[1].state.stacked();
  // R P R^T is symmetric to rounding; the node asks for symmetry to 1e-9: made exact here.
  e.cov1_eci = 0.5 * (in.obj[0].cov_eci + in.obj[0].cov_eci.transpose());
  e.cov2_eci = 0.5 * (in.obj[1].cov_eci + in.obj[1].cov_eci.transpose());
  e.hbr_m = in.hbr_m;
  e.pc_red = c.pc_red;
  e.pc_target = c.pc_target;
  e.burn_start_us = before_tca_us(e.tca_us, c.window_open_before_tca_s);
  e.burn_end_us = before_tca_us(e.tca_us, c.window_close_before_tca_s);
  e.veto_deadline_us = before_tca_us(e.tca_us, c.veto_deadline_before_tca_s);
  check_as_the_node(e, now_us, u.tca_utc);
  return u;
}

namespace {

std::string utc_of(std::int64_t utime_us) {
  return format_calendar_utc(calendar_from_seconds_since_j2000(seconds_since_j2000_from_unix_utime(utime_us)));
}

nlohmann::json time_json(std::int64_t utime_us) {
  return {{"utc", utc_of(utime_us)}, {"utime", utime_us}};
}

nlohmann::json object_json(const std::string& designator, const Vec6& x, const Mat6& p) {
  nlohmann::json cov = nlohmann::json::array();
  for (int i = 0; i < 6; ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (int j = 0; j < 6; ++j) row.push_back(p(i, j));
    cov.push_back(row);
  }
  return {{"designator", designator},
          {"r_eci_m", {x(0), x(1), x(2)}},
          {"v_eci_mps", {x(3), x(4), x(5)}},
          {"cov_eci", cov}};
}

}  // namespace

nlohmann::json to_json(const ConjunctionUplink& u) {
  const autonomy::ConjunctionEvent& e = u.event;
  return {{"source", u.source},
          {"message_id", u.message_id},
          {"creation_date", u.creation_date},
          {"event_id", e.event_id},
          {"version", e.version},
          {"tca", time_json(e.tca_us)},
          {"hbr_m", e.hbr_m},
          {"pc_red", e.pc_red},
          {"pc_target", e.pc_target},
          {"burn_window", {{"start", time_json(e.burn_start_us)}, {"end", time_json(e.burn_end_us)}}},
          {"veto_deadline", time_json(e.veto_deadline_us)},
          {"object1", object_json(u.object1, e.x1_eci, e.cov1_eci)},
          {"object2", object_json(u.object2, e.x2_eci, e.cov2_eci)},
          {"frames", "r_eci_m, v_eci_mps, cov_eci: ECI (J2000 axes), [r; v] in m, m/s"}};
}

}  // namespace evade::commands
