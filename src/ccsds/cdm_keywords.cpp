// CDM keyword tables: each section's keywords in order and their units (include/evade/ccsds/
// cdm.hpp; CCSDS 508.0-B-1 tables 3-2 header, 3-3 relative metadata/data, 3-4 object metadata,
// 3-5 OD and additional parameters, state vector, 3-6 covariance).
#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "evade/ccsds/cdm.hpp"
#include "evade/ccsds/internal/cdm_keyword_tables.hpp"

namespace evade::ccsds {
namespace {

const std::vector<std::string>& header_keywords() {
  static const std::vector<std::string> k = {"CCSDS_CDM_VERS", "CREATION_DATE", "ORIGINATOR",
                                             "MESSAGE_FOR", "MESSAGE_ID"};
  return k;
}
const std::vector<std::string>& relative_keywords() {
  static const std::vector<std::string> k = {
      "TCA", "MISS_DISTANCE", "RELATIVE_SPEED", "RELATIVE_POSITION_R", "RELATIVE_POSITION_T",
      "RELATIVE_POSITION_N", "RELATIVE_VELOCITY_R", "RELATIVE_VELOCITY_T", "RELATIVE_VELOCITY_N",
      "START_SCREEN_PERIOD", "STOP_SCREEN_PERIOD", "SCREEN_VOLUME_FRAME", "SCREEN_VOLUME_SHAPE",
      "SCREEN_VOLUME_X", "SCREEN_VOLUME_Y", "SCREEN_VOLUME_Z", "SCREEN_ENTRY_TIME",
      "SCREEN_EXIT_TIME", "COLLISION_PROBABILITY", "COLLISION_PROBABILITY_METHOD"};
  return k;
}
const std::vector<std::string>& metadata_keywords() {
  static const std::vector<std::string> k = {
      "OBJECT", "OBJECT_DESIGNATOR", "CATALOG_NAME", "OBJECT_NAME", "INTERNATIONAL_DESIGNATOR",
      "OBJECT_TYPE", "OPERATOR_CONTACT_POSITION", "OPERATOR_ORGANIZATION", "OPERATOR_PHONE",
      "OPERATOR_EMAIL", "EPHEMERIS_NAME", "COVARIANCE_METHOD", "MANEUVERABLE", "ORBIT_CENTER",
      "REF_FRAME", "GRAVITY_MODEL", "ATMOSPHERIC_MODEL", "N_BODY_PERTURBATIONS",
      "SOLAR_RAD_PRESSURE", "EARTH_TIDES", "INTRACK_THRUST"};
  return k;
}
const std::vector<std::string>& od_keywords() {
  static const std::vector<std::string> k = {
      "TIME_LASTOB_START", "TIME_LASTOB_END", "RECOMMENDED_OD_SPAN", "ACTUAL_OD_SPAN",
      "OBS_AVAILABLE", "OBS_USED", "TRACKS_AVAILABLE", "TRACKS_USED", "RESIDUALS_ACCEPTED",
      "WEIGHTED_RMS"};
  return k;
}
const std::vector<std::string>& additional_keywords() {
  static const std::vector<std::string> k = {"AREA_PC", "AREA_DRG", "AREA_SRP", "MASS",
                                             "CD_AREA_OVER_MASS", "CR_AREA_OVER_MASS",
                                             "THRUST_ACCELERATION", "SEDR"};
  return k;
}
const std::vector<std::string>& state_keywords() {
  static const std::vector<std::string> k = {"X", "Y", "Z", "X_DOT", "Y_DOT", "Z_DOT"};
  return k;
}
const char* const kCovAxes[9] = {"R", "T", "N", "RDOT", "TDOT", "NDOT", "DRG", "SRP", "THR"};

std::vector<std::string> covariance_keywords() {
  std::vector<std::string> k;
  const char* rows[9] = {"CR", "CT", "CN", "CRDOT", "CTDOT", "CNDOT", "CDRG", "CSRP", "CTHR"};
  for (int i = 0; i < 9; ++i) {
    for (int j = 0; j <= i; ++j) k.push_back(std::string(rows[i]) + "_" + kCovAxes[j]);
  }
  return k;
}

std::string covariance_unit(const std::string& key) {
  const auto us = key.find('_');
  const std::string row = key.substr(1, us - 1), col = key.substr(us + 1);
  auto kind = [](const std::string& a) {  // 0 pos, 1 vel, 2 drg/srp, 3 thr
    if (a == "R" || a == "T" || a == "N") return 0;
    if (a == "RDOT" || a == "TDOT" || a == "NDOT") return 1;
    return a == "THR" ? 3 : 2;
  };
  const int r = kind(row), c = kind(col);
  static const char* table[4][4] = {
      {"m**2", "m**2/s", "m**3/kg", "m**2/s**2"},
      {"m**2/s", "m**2/s**2", "m**3/(kg*s)", "m**2/s**3"},
      {"m**3/kg", "m**3/(kg*s)", "m**4/kg**2", "m**3/(kg*s**2)"},
      {"m**2/s**2", "m**2/s**3", "m**3/(kg*s**2)", "m**2/s**4"}};
  return table[r][c];
}

}  // namespace

namespace internal {

const std::vector<std::string>& covariance_keyword_table() {
  static const std::vector<std::string> k = covariance_keywords();
  return k;
}

}  // namespace internal

const std::vector<std::string>& cdm_section_keywords(CdmSectionId id) {
  switch (id) {
    case CdmSectionId::kHeader: return header_keywords();
    case CdmSectionId::kRelative: return relative_keywords();
    case CdmSectionId::kMetadata: return metadata_keywords();
    case CdmSectionId::kOd: return od_keywords();
    case CdmSectionId::kAdditional: return additional_keywords();
    case CdmSectionId::kState: return state_keywords();
    case CdmSectionId::kCovariance: return internal::covariance_keyword_table();
  }
  return header_keywords();
}

bool cdm_keyword_section(const std::string& key, CdmSectionId* id) {
  for (auto s : {CdmSectionId::kHeader, CdmSectionId::kRelative, CdmSectionId::kMetadata,
                 CdmSectionId::kOd, CdmSectionId::kAdditional, CdmSectionId::kState,
                 CdmSectionId::kCovariance}) {
    const auto& k = cdm_section_keywords(s);
    if (std::find(k.begin(), k.end(), key) != k.end()) {
      *id = s;
      return true;
    }
  }
  return false;
}

std::string cdm_keyword_unit(const std::string& key) {
  static const std::map<std::string, std::string> units = {
      {"MISS_DISTANCE", "m"}, {"RELATIVE_SPEED", "m/s"}, {"RELATIVE_POSITION_R", "m"},
      {"RELATIVE_POSITION_T", "m"}, {"RELATIVE_POSITION_N", "m"},
      {"RELATIVE_VELOCITY_R", "m/s"}, {"RELATIVE_VELOCITY_T", "m/s"},
      {"RELATIVE_VELOCITY_N", "m/s"}, {"SCREEN_VOLUME_X", "m"}, {"SCREEN_VOLUME_Y", "m"},
      {"SCREEN_VOLUME_Z", "m"}, {"RECOMMENDED_OD_SPAN", "d"}, {"ACTUAL_OD_SPAN", "d"},
      {"RESIDUALS_ACCEPTED", "%"}, {"AREA_PC", "m**2"}, {"AREA_DRG", "m**2"},
      {"AREA_SRP", "m**2"}, {"MASS", "kg"}, {"CD_AREA_OVER_MASS", "m**2/kg"},
      {"CR_AREA_OVER_MASS", "m**2/kg"}, {"THRUST_ACCELERATION", "m/s**2"}, {"SEDR", "W/kg"},
      {"X", "km"}, {"Y", "km"}, {"Z", "km"}, {"X_DOT", "km/s"}, {"Y_DOT", "km/s"},
      {"Z_DOT", "km/s"}};
  const auto u = units.find(key);
  if (u != units.end()) return u->second;
  CdmSectionId id;
  if (cdm_keyword_section(key, &id) && id == CdmSectionId::kCovariance) return covariance_unit(key);
  return "";
}

}  // namespace evade::ccsds
