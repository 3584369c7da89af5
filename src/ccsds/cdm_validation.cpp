// CDM checks (validate_cdm, cdm_unit_notes; include/evade/ccsds/cdm.hpp): each keyword once
// and in its section, the mandatory ones present, values of their kind, units the standard's
// or an equivalent spelling, enumerated values the standard's (CCSDS 508.0-B-1 tables 3-2 to
// 3-6).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "evade/ccsds/cdm.hpp"
#include "evade/core/epoch.hpp"

namespace evade::ccsds {
namespace {

enum class Kind { kText, kNumber, kEpoch };

const std::set<std::string>& mandatory_keywords() {
  static const std::set<std::string> k = {
      "CCSDS_CDM_VERS", "CREATION_DATE", "ORIGINATOR", "MESSAGE_ID", "TCA", "MISS_DISTANCE",
      "OBJECT", "OBJECT_DESIGNATOR", "CATALOG_NAME", "OBJECT_NAME", "INTERNATIONAL_DESIGNATOR",
      "EPHEMERIS_NAME", "COVARIANCE_METHOD", "MANEUVERABLE", "REF_FRAME", "X", "Y", "Z", "X_DOT",
      "Y_DOT", "Z_DOT"};
  return k;
}

const std::set<std::string>& epoch_keywords() {
  static const std::set<std::string> k = {
      "CREATION_DATE",     "TCA",              "START_SCREEN_PERIOD", "STOP_SCREEN_PERIOD",
      "SCREEN_ENTRY_TIME", "SCREEN_EXIT_TIME", "TIME_LASTOB_START",   "TIME_LASTOB_END"};
  return k;
}

const std::map<std::string, std::vector<std::string>>& enum_values() {
  static const std::map<std::string, std::vector<std::string>> k = {
      {"OBJECT", {"OBJECT1", "OBJECT2"}},
      {"MANEUVERABLE", {"YES", "NO", "N/A"}},
      {"COVARIANCE_METHOD", {"CALCULATED", "DEFAULT"}},
      {"REF_FRAME", {"EME2000", "GCRF", "ITRF"}},
      {"SCREEN_VOLUME_FRAME", {"RTN", "TVN"}},
      {"SCREEN_VOLUME_SHAPE", {"ELLIPSOID", "BOX"}},
      {"OBJECT_TYPE", {"PAYLOAD", "ROCKET BODY", "DEBRIS", "UNKNOWN", "OTHER"}},
      {"SOLAR_RAD_PRESSURE", {"YES", "NO"}},
      {"EARTH_TIDES", {"YES", "NO"}},
      {"INTRACK_THRUST", {"YES", "NO"}}};
  return k;
}

Kind keyword_kind(const std::string& key, CdmSectionId id) {
  if (epoch_keywords().count(key)) return Kind::kEpoch;
  if (id == CdmSectionId::kCovariance || id == CdmSectionId::kState ||
      id == CdmSectionId::kAdditional)
    return Kind::kNumber;
  static const std::set<std::string> numbers = {
      "CCSDS_CDM_VERS", "MISS_DISTANCE", "RELATIVE_SPEED", "RELATIVE_POSITION_R",
      "RELATIVE_POSITION_T", "RELATIVE_POSITION_N", "RELATIVE_VELOCITY_R",
      "RELATIVE_VELOCITY_T", "RELATIVE_VELOCITY_N", "SCREEN_VOLUME_X", "SCREEN_VOLUME_Y",
      "SCREEN_VOLUME_Z", "COLLISION_PROBABILITY", "RECOMMENDED_OD_SPAN", "ACTUAL_OD_SPAN",
      "OBS_AVAILABLE", "OBS_USED", "TRACKS_AVAILABLE", "TRACKS_USED", "RESIDUALS_ACCEPTED",
      "WEIGHTED_RMS"};
  return numbers.count(key) ? Kind::kNumber : Kind::kText;
}

[[noreturn]] void fail(const CdmItem& it, const std::string& what) {
  throw CdmError("CDM line " + std::to_string(it.line) + ": keyword '" + it.key + "': " + what);
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// One base unit and its optional '**n' exponent (n in [-9, 9]) at u[*i]; *i moves past it.
// False when there is none there.
bool read_unit_factor(const std::string& u, std::size_t* i, std::string* base, int* power) {
  std::size_t j = *i;
  while (j < u.size() && (std::isalpha(static_cast<unsigned char>(u[j])) != 0 || u[j] == '%')) ++j;
  if (j == *i) return false;
  *base = u.substr(*i, j - *i);
  *power = 1;
  if (u.compare(j, 2, "**") == 0) {
    char* end = nullptr;
    const long p = std::strtol(u.c_str() + j + 2, &end, 10);
    if (end == u.c_str() + j + 2 || p < -9 || p > 9) return false;
    *power = static_cast<int>(p);
    j = static_cast<std::size_t>(end - u.c_str());
  }
  *i = j;
  return true;
}

// The signs in force while a unit expression is read.
struct UnitSigns {
  int next = 1;   // the next factor's sign: -1 after '/'
  int group = 1;  // the sign of the parenthesized group being read
};

enum class UnitMark { kNone, kRead, kBad };

// A separator ('*', '/') or parenthesis at c, applied to *s; kNone when c is none of them,
// kBad for a second level of parentheses.
UnitMark read_unit_mark(char c, UnitSigns* s) {
  switch (c) {
    case '/':
      s->next = -1;
      return UnitMark::kRead;
    case '*':
      return UnitMark::kRead;
    case '(':
      if (s->group != 1) return UnitMark::kBad;  // one level only
      s->group = s->next;
      s->next = 1;
      return UnitMark::kRead;
    case ')':
      s->group = 1;
      s->next = 1;
      return UnitMark::kRead;
    default:
      return UnitMark::kNone;
  }
}

// A unit expression as base units with integer exponents ("M**3/(KG*S)" and "M**3/KG/S" and
// "M**3*KG**-1*S**-1" all give {M: 3, KG: -1, S: -1}); false when it is not one (the spellings
// CCSDS 508.0-B-1 and other implementations write: factors joined by '*' and '/', '**n'
// exponents, one level of parentheses after '/').
bool unit_exponents(const std::string& unit, std::map<std::string, int>* out) {
  std::map<std::string, int> ex;
  UnitSigns s;
  std::size_t i = 0;
  const std::string u = upper(unit);
  while (i < u.size()) {
    const UnitMark m = read_unit_mark(u[i], &s);
    if (m == UnitMark::kBad) return false;
    if (m == UnitMark::kRead) {
      ++i;
      continue;
    }
    std::string base;
    int power = 1;
    if (!read_unit_factor(u, &i, &base, &power)) return false;
    ex[base] += s.next * s.group * power;
    if (s.group == 1) s.next = 1;  // outside a group '/' applies to one factor
  }
  for (auto it = ex.begin(); it != ex.end();) it = it->second == 0 ? ex.erase(it) : std::next(it);
  *out = std::move(ex);
  return true;
}

bool same_unit(const std::string& a, const std::string& b) {
  if (upper(a) == upper(b)) return true;
  std::map<std::string, int> ea, eb;
  return unit_exponents(a, &ea) && unit_exponents(b, &eb) && ea == eb;
}

// A diagonal term of the covariance (CR_R, CRDOT_RDOT, CDRG_DRG, ...): C<a>_<a>.
bool is_variance(const std::string& key) {
  const std::size_t u = key.find('_');
  return key.size() > 2 && key[0] == 'C' && u != std::string::npos &&
         key.compare(1, u - 1, key, u + 1, std::string::npos) == 0;
}

// The value as its keyword's kind wants it: a finite number, an epoch, or any text; a
// variance (a diagonal covariance term) not negative.
void check_value(const CdmItem& it, CdmSectionId id) {
  const Kind k = keyword_kind(it.key, id);
  if (k == Kind::kNumber) {
    char* end = nullptr;
    const double v = std::strtod(it.value.c_str(), &end);
    if (end == it.value.c_str() || *end != '\0' || !std::isfinite(v))
      fail(it, "expected a number, found '" + it.value + "'");
  } else if (k == Kind::kEpoch) {
    try {
      (void)parse_calendar_utc(it.value);
    } catch (const std::exception&) {
      fail(it, "expected an epoch YYYY-MM-DDThh:mm:ss[.d], found '" + it.value + "'");
    }
  }
  if (id == CdmSectionId::kCovariance && is_variance(it.key) && std::strtod(it.value.c_str(), nullptr) < 0.0) {
    fail(it, "a variance cannot be negative, found '" + it.value + "' (malformed covariance)");
  }
}

// A unit, when written, the standard's or an equivalent spelling of it.
void check_unit(const CdmItem& it) {
  const std::string unit = cdm_keyword_unit(it.key);
  if (!it.unit.empty() && !same_unit(it.unit, unit))
    fail(it, "expected unit [" + (unit.empty() ? std::string("none") : unit) + "], found [" +
                 it.unit + "]");
}

// An enumerated keyword's value one of the standard's (any case).
void check_enum(const CdmItem& it) {
  const auto e = enum_values().find(it.key);
  if (e != enum_values().end() &&
      std::find(e->second.begin(), e->second.end(), upper(it.value)) == e->second.end()) {
    std::string allowed;
    for (const auto& a : e->second) allowed += (allowed.empty() ? "" : ", ") + a;
    fail(it, "expected one of " + allowed + ", found '" + it.value + "'");
  }
}

void check_item(const CdmItem& it, CdmSectionId id) {
  if (it.key == "COMMENT") return;
  if (it.value.empty()) fail(it, "expected a value, found none");
  check_value(it, id);
  check_unit(it);
  check_enum(it);
}

void check_section(const CdmSection& s, CdmSectionId id, int last_line,
                   const std::string& where) {
  std::set<std::string> seen;
  for (const CdmItem& it : s.items) {
    CdmSectionId sid;
    if (it.key != "COMMENT" && (!cdm_keyword_section(it.key, &sid) || sid != id))
      fail(it, "not a keyword of the " + where + " section");
    if (it.key != "COMMENT" && !seen.insert(it.key).second) fail(it, "given twice in " + where);
    check_item(it, id);
  }
  std::vector<std::string> required;
  const auto& kw = cdm_section_keywords(id);
  for (std::size_t n = 0; n < kw.size(); ++n) {
    if (mandatory_keywords().count(kw[n]) || (id == CdmSectionId::kCovariance && n < 21))
      required.push_back(kw[n]);
  }
  const auto missing = [&](const std::string& k) {
    return CdmError("CDM line " + std::to_string(last_line) + ": keyword '" + k +
                    "': mandatory in " + where + " but missing");
  };
  for (const auto& k : required) {
    if (!seen.count(k)) {
      throw missing(k);
    }
  }
}

int last_line(const Cdm& c) {
  int l = 0;
  const CdmSection* all[] = {&c.header, &c.relative};
  for (const CdmSection* s : all)
    for (const auto& it : s->items) l = std::max(l, it.line);
  for (const auto& o : c.object) {
    for (auto id : {CdmSectionId::kMetadata, CdmSectionId::kOd, CdmSectionId::kAdditional,
                    CdmSectionId::kState, CdmSectionId::kCovariance})
      for (const auto& it : o.section(id).items) l = std::max(l, it.line);
  }
  return l;
}

}  // namespace

void validate_cdm(const Cdm& c) {
  const int end = last_line(c);
  check_section(c.header, CdmSectionId::kHeader, end, "the header");
  check_section(c.relative, CdmSectionId::kRelative, end, "the relative metadata/data");
  for (int i = 0; i < 2; ++i) {
    const std::string where = "object " + std::to_string(i + 1);
    const CdmObject& o = c.object[i];
    check_section(o.metadata, CdmSectionId::kMetadata, end, where + " metadata");
    check_section(o.od_parameters, CdmSectionId::kOd, end, where + " OD parameters");
    check_section(o.additional_parameters, CdmSectionId::kAdditional, end,
                  where + " additional parameters");
    check_section(o.state_vector, CdmSectionId::kState, end, where + " state vector");
    check_section(o.covariance, CdmSectionId::kCovariance, end, where + " covariance");
    const CdmItem* obj = o.metadata.find("OBJECT");
    const std::string want = i == 0 ? "OBJECT1" : "OBJECT2";
    if (upper(obj->value) != want) fail(*obj, "expected " + want + ", found '" + obj->value + "'");
  }
}

std::vector<std::string> cdm_unit_notes(const Cdm& c) {
  std::vector<std::string> notes;
  auto scan = [&notes](const CdmSection& s) {
    for (const CdmItem& it : s.items) {
      const std::string unit = cdm_keyword_unit(it.key);
      if (it.unit.empty() || upper(it.unit) == upper(unit)) continue;
      notes.push_back("keyword '" + it.key + "' (line " + std::to_string(it.line) + "): unit [" +
                      it.unit + "] read as the standard's equivalent [" + unit + "]");
    }
  };
  scan(c.header);
  scan(c.relative);
  for (const CdmObject& o : c.object) {
    for (const CdmSection* s : {&o.metadata, &o.od_parameters, &o.additional_parameters,
                                &o.state_vector, &o.covariance}) {
      scan(*s);
    }
  }
  return notes;
}

}  // namespace evade::ccsds
