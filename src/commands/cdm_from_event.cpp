// A screening event as a CCSDS 508.0-B-1 CDM (include/evade/commands/cdm_from_event.hpp
// gives the keywords written and the sources: CCSDS 508.0-B-1 tables 3-2 to 3-6; the Pc is
// the recommended one of pc_method_choice.hpp: Foster & Estes 1992 unless its usage checks
// fail).
#include "evade/commands/cdm_from_event.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "evade/assessment/assess.hpp"
#include "evade/assessment/pc_method_choice.hpp"
#include "evade/assessment/covariance.hpp"
#include "evade/core/constants.hpp"
#include "evade/core/epoch.hpp"
#include "evade/core/frames.hpp"

namespace evade::commands {
namespace {

std::string fmt(const char* f, double v) {
  char b[64];
  const int n = std::snprintf(b, sizeof b, f, v);
  if (n < 0 || n >= static_cast<int>(sizeof b)) {  // never for an orbit: %.9f needs v > 1e50
    throw std::invalid_argument(std::string("CDM value ") + std::to_string(v) +
                                " does not fit the field format " + f);
  }
  return b;
}

void add(ccsds::CdmSection& s, const std::string& key, const std::string& value,
         const std::string& unit = "") {
  s.items.push_back({key, value, unit, 0});
}
void add_comment(ccsds::CdmSection& s, const std::string& text) {
  if (!text.empty()) s.items.push_back({"COMMENT", text, "", 0});
}

void check_finite(const StateEci& s, const std::string& who) {
  if (!s.r_eci_m.allFinite() || !s.v_eci_mps.allFinite())
    throw std::invalid_argument("CDM from event: " + who + ": state is not finite");
}

void check_cov(const Mat6& c, const std::string& who) {
  if (!c.allFinite() || !(c - c.transpose()).isZero(1e-12 * (1.0 + c.cwiseAbs().maxCoeff())))
    throw std::invalid_argument("CDM from event: " + who +
                                ": RTN covariance is not finite and symmetric");
}

void metadata(ccsds::CdmSection& m, const EventObject& o, int i) {
  add_comment(m, o.state_comment);
  add(m, "OBJECT", i == 0 ? "OBJECT1" : "OBJECT2");
  add(m, "OBJECT_DESIGNATOR", o.designator);
  add(m, "CATALOG_NAME", o.catalog_name.empty() ? "UNKNOWN" : o.catalog_name);
  add(m, "OBJECT_NAME", o.name.empty() ? o.designator : o.name);
  add(m, "INTERNATIONAL_DESIGNATOR",
      o.international_designator.empty() ? "UNKNOWN" : o.international_designator);
  add(m, "EPHEMERIS_NAME", "NONE");
  // DEFAULT: the covariance (assumed or absent) does not come from an orbit determination.
  add(m, "COVARIANCE_METHOD", "DEFAULT");
  add(m, "MANEUVERABLE", "N/A");
  add(m, "REF_FRAME", "EME2000");
}

void state_vector(ccsds::CdmSection& s, const StateEci& x) {
  const char* pk[3] = {"X", "Y", "Z"};
  const char* vk[3] = {"X_DOT", "Y_DOT", "Z_DOT"};
  for (int k = 0; k < 3; ++k) add(s, pk[k], fmt("%.9f", x.r_eci_m(k) * 1e-3), "km");
  for (int k = 0; k < 3; ++k) add(s, vk[k], fmt("%.12f", x.v_eci_mps(k) * 1e-3), "km/s");
}

void covariance(ccsds::CdmSection& s, const EventObject& o) {
  if (o.cov_rtn) {
    add_comment(s, o.cov_comment);
  } else {
    add_comment(s, "covariance not known: the 21 terms CCSDS 508.0-B-1 requires are written "
                   "as 0; this is not a covariance and no collision probability is given");
  }
  const Mat6 c = o.cov_rtn ? *o.cov_rtn : Mat6::Zero();
  const auto& keys = ccsds::cdm_section_keywords(ccsds::CdmSectionId::kCovariance);
  for (Eigen::Index r = 0; r < 6; ++r) {
    for (Eigen::Index k = 0; k <= r; ++k) {
      const std::string& key = keys[static_cast<std::size_t>(r * (r + 1) / 2 + k)];
      add(s, key, fmt("%.15e", c(r, k)), ccsds::cdm_keyword_unit(key));
    }
  }
}

void relative(ccsds::CdmSection& s, const ScreeningEvent& ev) {
  add(s, "TCA", cdm_epoch(ev.tca_utc_j2000_s));
  add(s, "MISS_DISTANCE", fmt("%.6f", ev.miss_m), "m");
  add(s, "RELATIVE_SPEED", fmt("%.6f", ev.rel_speed_mps), "m/s");
  const StateEci& a = ev.obj[0].state_eme2000;
  const StateEci& b = ev.obj[1].state_eme2000;
  const Mat3 rtn = rotation_eci_to_rsw(a);
  const Vec3 dr = rtn * (b.r_eci_m - a.r_eci_m), dv = rtn * (b.v_eci_mps - a.v_eci_mps);
  const char* ax[3] = {"R", "T", "N"};
  for (int k = 0; k < 3; ++k)
    add(s, std::string("RELATIVE_POSITION_") + ax[k], fmt("%.6f", dr(k)), "m");
  for (int k = 0; k < 3; ++k)
    add(s, std::string("RELATIVE_VELOCITY_") + ax[k], fmt("%.6f", dv(k)), "m/s");
  if (ev.screen_stop_utc_j2000_s > ev.screen_start_utc_j2000_s) {
    add(s, "START_SCREEN_PERIOD", cdm_epoch(ev.screen_start_utc_j2000_s));
    add(s, "STOP_SCREEN_PERIOD", cdm_epoch(ev.screen_stop_utc_j2000_s));
  }
  if (ev.screen_threshold_m > 0.0) {
    add(s, "SCREEN_VOLUME_FRAME", "RTN");
    add(s, "SCREEN_VOLUME_SHAPE", "ELLIPSOID");
    for (const char* k : {"SCREEN_VOLUME_X", "SCREEN_VOLUME_Y", "SCREEN_VOLUME_Z"})
      add(s, k, fmt("%.3f", ev.screen_threshold_m), "m");
  }
}

// The recommended Pc of the event (pc_method_choice.hpp: 2D unless its usage checks fail)
// from the RTN covariances rotated to EME2000, at the event's TCA.
assessment::PcChoice event_pc(const ScreeningEvent& ev, const EventCdmOptions& opt) {
  assessment::ConjunctionInput in;
  in.hbr_m = opt.hbr_m;
  for (int i = 0; i < 2; ++i) {
    const auto& cov_rtn = ev.obj[i].cov_rtn;
    if (!cov_rtn) throw std::invalid_argument("CDM from event: the Pc needs both covariances");
    in.obj[i].name = ev.obj[i].name;
    in.obj[i].state = ev.obj[i].state_eme2000;
    in.obj[i].cov_eci = assessment::cov_eci_from_rtn(*cov_rtn, in.obj[i].state);
    in.obj[i].has_velocity_cov = true;
  }
  assessment::AssessConfig cfg = opt.assess;
  cfg.tca_search_s = 0.0;  // the screener's TCA
  const assessment::Assessment a = assessment::assess(in, cfg);
  return assessment::choose_pc(a, in.hbr_m, cfg, in.earth, true);
}

// The CCSDS name of a recommended method (its row's SANA Pc-method code, pc_methods.hpp).
const char* pc_method_code(const std::string& method) {
  const assessment::PcMethodRow* row = assessment::pc_method_named(method);
  if (row == nullptr || row->cdm_code == nullptr)
    throw std::logic_error("CDM from event: no CCSDS code for the Pc method '" + method + "'");
  return row->cdm_code;
}

void check_event(const ScreeningEvent& ev, const EventCdmOptions& opt, bool cov_known) {
  if (!std::isfinite(ev.tca_utc_j2000_s) || !std::isfinite(ev.miss_m) || ev.miss_m < 0.0 ||
      !std::isfinite(ev.rel_speed_mps) || ev.rel_speed_mps < 0.0)
    throw std::invalid_argument("CDM from event: TCA, miss or relative speed is not a finite "
                                "number >= 0");
  for (int i = 0; i < 2; ++i) {
    const std::string who = "object " + std::to_string(i + 1) + " (" + ev.obj[i].designator + ")";
    if (ev.obj[i].designator.empty())
      throw std::invalid_argument("CDM from event: object " + std::to_string(i + 1) +
                                  ": OBJECT_DESIGNATOR is empty");
    check_finite(ev.obj[i].state_eme2000, who);
    const auto& cov_rtn = ev.obj[i].cov_rtn;
    if (cov_rtn) check_cov(*cov_rtn, who);
  }
  if (cov_known && !(opt.hbr_m > 0.0 && std::isfinite(opt.hbr_m)))
    throw std::invalid_argument("CDM from event: covariances are known but the hard-body "
                                "radius is not a number > 0 m: no collision probability");
  if (cov_known && !(ev.rel_speed_mps > 0.0))
    throw std::invalid_argument("CDM from event: relative speed 0: no encounter plane");
}

}  // namespace

std::string cdm_epoch(double utc_j2000_s) {
  // Rounded to the microsecond: the 9-digit text of t + 0.5 us, truncated to 6 digits.
  std::string s = format_calendar_utc(calendar_from_seconds_since_j2000(utc_j2000_s + 5e-7));
  s[10] = 'T';
  const auto dot = s.find('.');
  if (dot != std::string::npos && s.size() > dot + 7) s.resize(dot + 7);
  return s;
}

std::string cdm_event_file_stem(const ScreeningEvent& ev) {
  std::string t;
  for (char c : cdm_epoch(ev.tca_utc_j2000_s))
    if (c != '-' && c != ':') t += c;
  std::string s = ev.obj[0].designator + "_" + ev.obj[1].designator + "_" + t;
  for (char& c : s) {
    const bool ok = std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '.';
    if (!ok) c = '_';
  }
  return s;
}

EventCdm cdm_from_event(const ScreeningEvent& ev, const EventCdmOptions& opt) {
  const bool cov_known = ev.obj[0].cov_rtn.has_value() && ev.obj[1].cov_rtn.has_value();
  check_event(ev, opt, cov_known);
  EventCdm out;
  ccsds::Cdm& c = out.cdm;
  add(c.header, "CCSDS_CDM_VERS", "1.0");
  add_comment(c.header, opt.header_comment);
  add(c.header, "CREATION_DATE", cdm_epoch(opt.creation_utc_j2000_s));
  add(c.header, "ORIGINATOR", opt.originator);
  add(c.header, "MESSAGE_ID", opt.message_id.empty() ? cdm_event_file_stem(ev) : opt.message_id);
  std::optional<assessment::PcChoice> pc;
  if (cov_known) {
    pc = event_pc(ev, opt);
    add_comment(c.relative, "hard-body radius for COLLISION_PROBABILITY: " +
                                fmt("%.6f", opt.hbr_m) + " m" +
                                (opt.hbr_source.empty() ? "" : " (" + opt.hbr_source + ")"));
    add_comment(c.relative, "COLLISION_PROBABILITY by " + pc->method + " (" + pc->why + ")");
  }
  relative(c.relative, ev);
  if (pc) {
    out.pc = pc->pc;
    out.pc_method = pc->method;
    add(c.relative, "COLLISION_PROBABILITY", fmt("%.10e", *out.pc));
    add(c.relative, "COLLISION_PROBABILITY_METHOD", pc_method_code(pc->method));
  }
  for (int i = 0; i < 2; ++i) {
    const EventObject& o = ev.obj[i];
    ccsds::CdmObject& co = c.object[i];
    metadata(co.metadata, o, i);
    if (o.radius_m > 0.0)
      add(co.additional_parameters, "AREA_PC", fmt("%.15e", kPi * o.radius_m * o.radius_m), "m**2");
    state_vector(co.state_vector, o.state_eme2000);
    covariance(co.covariance, o);
  }
  ccsds::validate_cdm(c);
  return out;
}

}  // namespace evade::commands
