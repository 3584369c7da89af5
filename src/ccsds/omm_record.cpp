// OMM keyword set -> SGP4 mean elements, CCSDS 502.0-B-2 "Orbit Data Messages", section 4
// (OMM: metadata, mean Keplerian elements, TLE-related parameters, units of each keyword).
#include "evade/ccsds/omm_record.hpp"

#include <set>

#include "evade/sgp4/catalog.hpp"
#include "evade/sgp4/text_fields.hpp"

namespace evade::ccsds {

using sgp4::Catalog;
using sgp4::MeanElements;
using sgp4::ReadError;
using sgp4::ReadIssue;
using sgp4::trim;
using sgp4::parse_plain_decimal;
using sgp4::parse_plain_integer;
using sgp4::parse_iso_epoch;
using sgp4::title_to_utf8;
namespace {

[[noreturn]] void fail(const std::string& source, const OmmValue& v, const std::string& expected) {
  throw ReadError(ReadIssue{source, v.line, v.column, expected, v.text});
}

// A text value (a name or an id) as UTF-8 (sgp4::title_to_utf8: UTF-8 kept, anything else read
// as Latin-1), "" when absent; a control character in it is an error at the value's position.
std::string text_value(const OmmRecord& rec, const std::string& key, const std::string& source) {
  const auto it = rec.values.find(key);
  if (it == rec.values.end()) return "";
  std::string out;
  long control = 0;
  if (title_to_utf8(trim(it->second.text), &out, &control) > 0) {
    throw ReadError(ReadIssue{source, it->second.line, it->second.column,
                              key + " of printable characters (UTF-8 or Latin-1)",
                              sgp4::code_point_name(control)});
  }
  return out;
}

const OmmValue& required(const OmmRecord& rec, const std::string& key, const std::string& source) {
  const auto it = rec.values.find(key);
  if (it == rec.values.end())
    throw ReadError(ReadIssue{source, rec.line, 0, "keyword " + key + " in the entry beginning here", "none"});
  return it->second;
}

double number(const OmmRecord& rec, const std::string& key, const std::string& source, double lo,
              double hi, const std::string& range) {
  const OmmValue& v = required(rec, key, source);
  double x = 0.0;
  if (!parse_plain_decimal(v.text, x) || !(x >= lo && x <= hi)) fail(source, v, key + " as a number in " + range);
  return x;
}

long optional_integer(const OmmRecord& rec, const std::string& key, const std::string& source, long lo,
                      long hi) {
  const auto it = rec.values.find(key);
  if (it == rec.values.end() || trim(it->second.text).empty()) return 0;
  long x = 0;
  if (!parse_plain_integer(it->second.text, x) || x < lo || x > hi)
    fail(source, it->second, key + " as an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return x;
}

void check_metadata(const OmmRecord& rec, const std::string& source) {
  const std::pair<const char*, std::set<std::string>> rules[] = {
      {"MEAN_ELEMENT_THEORY", {"SGP4", "SGP/SGP4", "SGP4-XP"}},
      {"REF_FRAME", {"TEME"}},
      {"TIME_SYSTEM", {"UTC"}},
      {"CENTER_NAME", {"EARTH"}}};
  for (const auto& [key, allowed] : rules) {
    const auto it = rec.values.find(key);
    if (it == rec.values.end()) continue;
    if (!allowed.count(trim(it->second.text))) {
      std::string list;
      for (const auto& a : allowed) list += (list.empty() ? "" : " or ") + a;
      fail(source, it->second, std::string(key) + " = " + list);
    }
  }
  if (rec.values.count("MEAN_ELEMENT_THEORY") && trim(rec.values.at("MEAN_ELEMENT_THEORY").text) == "SGP4-XP")
    fail(source, rec.values.at("MEAN_ELEMENT_THEORY"), "MEAN_ELEMENT_THEORY = SGP4 (SGP4-XP elements need another theory)");
}

}  // namespace

void add_omm_record(const OmmRecord& rec, const std::string& source, Catalog* cat) {
  try {
    cat->objects.push_back(mean_elements_from_omm(rec, source));
  } catch (const ReadError& e) {
    cat->issues.push_back(e.issue);
    ++cat->bad_entries;
  }
}

MeanElements mean_elements_from_omm(const OmmRecord& rec, const std::string& source) {
  check_metadata(rec, source);
  MeanElements m;
  m.source_line = rec.line;
  m.name = text_value(rec, "OBJECT_NAME", source);
  m.object_id = text_value(rec, "OBJECT_ID", source);
  const OmmValue& epoch = required(rec, "EPOCH", source);
  if (!parse_iso_epoch(epoch.text, m.epoch_year, m.epoch_day_of_year))
    fail(source, epoch, "EPOCH as an ISO 8601 UTC time YYYY-MM-DDThh:mm:ss[.f] (or YYYY-DDDThh:mm:ss) in 1957..2099");
  m.mean_motion_revpday = number(rec, "MEAN_MOTION", source, 1e-9, 20.0, "(0, 20) rev/day");
  m.eccentricity = number(rec, "ECCENTRICITY", source, 0.0, 0.9999999, "[0, 1)");
  m.inclination_deg = number(rec, "INCLINATION", source, 0.0, 180.0, "[0, 180] deg");
  m.raan_deg = number(rec, "RA_OF_ASC_NODE", source, 0.0, 360.0, "[0, 360] deg");
  m.arg_perigee_deg = number(rec, "ARG_OF_PERICENTER", source, 0.0, 360.0, "[0, 360] deg");
  m.mean_anomaly_deg = number(rec, "MEAN_ANOMALY", source, 0.0, 360.0, "[0, 360] deg");
  m.bstar_per_er = number(rec, "BSTAR", source, -1.0, 1.0, "[-1, 1] 1/ER");
  m.mean_motion_dot_revpday2 = number(rec, "MEAN_MOTION_DOT", source, -1.0, 1.0, "[-1, 1] rev/day^2");
  m.mean_motion_ddot_revpday3 = number(rec, "MEAN_MOTION_DDOT", source, -1.0, 1.0, "[-1, 1] rev/day^3");
  const OmmValue& id = required(rec, "NORAD_CAT_ID", source);
  long n = 0;
  if (!parse_plain_integer(id.text, n) || n < 1 || n > 339999) fail(source, id, "NORAD_CAT_ID as an integer in [1, 339999]");
  m.norad_id = n;
  if (rec.values.count("CLASSIFICATION_TYPE")) {
    const OmmValue& c = rec.values.at("CLASSIFICATION_TYPE");
    const std::string t = trim(c.text);
    if (t != "U" && t != "C" && t != "S") fail(source, c, "CLASSIFICATION_TYPE U, C or S");
    m.classification = t[0];
  }
  m.ephemeris_type = static_cast<int>(optional_integer(rec, "EPHEMERIS_TYPE", source, 0, 9));
  m.element_set_no = static_cast<int>(optional_integer(rec, "ELEMENT_SET_NO", source, 0, 9999));
  m.rev_at_epoch = optional_integer(rec, "REV_AT_EPOCH", source, 0, 9999999);
  return m;
}

bool is_omm_keyword(const std::string& key) {
  static const std::set<std::string> kKeys = {
      "CCSDS_OMM_VERS", "COMMENT", "CLASSIFICATION", "CREATION_DATE", "ORIGINATOR", "MESSAGE_ID",
      "OBJECT_NAME", "OBJECT_ID", "CENTER_NAME", "REF_FRAME", "REF_FRAME_EPOCH", "TIME_SYSTEM",
      "MEAN_ELEMENT_THEORY", "EPOCH", "SEMI_MAJOR_AXIS", "MEAN_MOTION", "ECCENTRICITY",
      "INCLINATION", "RA_OF_ASC_NODE", "ARG_OF_PERICENTER", "MEAN_ANOMALY", "GM",
      "MASS", "SOLAR_RAD_AREA", "SOLAR_RAD_COEFF", "DRAG_AREA", "DRAG_COEFF",
      "EPHEMERIS_TYPE", "CLASSIFICATION_TYPE", "NORAD_CAT_ID", "ELEMENT_SET_NO", "REV_AT_EPOCH",
      "BSTAR", "BTERM", "MEAN_MOTION_DOT", "MEAN_MOTION_DDOT", "AGOM", "COV_REF_FRAME",
      "CX_X", "CY_X", "CY_Y", "CZ_X", "CZ_Y", "CZ_Z", "CX_DOT_X", "CX_DOT_Y", "CX_DOT_Z",
      "CX_DOT_X_DOT", "CY_DOT_X", "CY_DOT_Y", "CY_DOT_Z", "CY_DOT_X_DOT", "CY_DOT_Y_DOT",
      "CZ_DOT_X", "CZ_DOT_Y", "CZ_DOT_Z", "CZ_DOT_X_DOT", "CZ_DOT_Y_DOT", "CZ_DOT_Z_DOT"};
  return kKeys.count(key) > 0 || key.rfind("USER_DEFINED_", 0) == 0;
}

}  // namespace evade::ccsds
