// One CCSDS OMM (502.0-B-2/3) entry as keyword -> value pairs, whatever its form (KVN, XML,
// the JSON and CSV "GP" forms), and its conversion to MeanElements with every value checked.
// Keywords: EPOCH, MEAN_MOTION (rev/day), ECCENTRICITY, INCLINATION, RA_OF_ASC_NODE,
// ARG_OF_PERICENTER, MEAN_ANOMALY (deg), NORAD_CAT_ID, BSTAR (1/ER), MEAN_MOTION_DOT,
// MEAN_MOTION_DDOT are required (the SGP4 theory's tleParameters); OBJECT_NAME, OBJECT_ID,
// CLASSIFICATION_TYPE, EPHEMERIS_TYPE, ELEMENT_SET_NO, REV_AT_EPOCH are optional; when
// given, MEAN_ELEMENT_THEORY must be SGP4 (or SGP/SGP4), REF_FRAME TEME, TIME_SYSTEM UTC
// and CENTER_NAME EARTH.
#pragma once

#include "evade/sgp4/catalog.hpp"

#include <map>
#include <string>

#include "evade/sgp4/mean_elements.hpp"

namespace evade::ccsds {

struct OmmValue {
  std::string text;
  int line = 0;
  int column = 0;
};

struct OmmRecord {
  std::map<std::string, OmmValue> values;
  int line = 0;  ///< where the entry begins
};

/// Converts one record; throws sgp4::ReadError (sgp4/catalog.hpp) naming the keyword, its line and
/// column, and what was expected, for a missing or bad value.
sgp4::MeanElements mean_elements_from_omm(const OmmRecord& rec, const std::string& source);

/// Converts rec into cat: its mean elements appended to cat->objects, or the ReadError the
/// conversion throws as one issue (one bad entry).
void add_omm_record(const OmmRecord& rec, const std::string& source, sgp4::Catalog* cat);

/// True for keywords of the OMM standard (header, metadata, mean elements, TLE parameters,
/// spacecraft parameters, covariance, user-defined USER_DEFINED_*); the strict forms (KVN,
/// XML) reject any other keyword.
bool is_omm_keyword(const std::string& key);

}  // namespace evade::ccsds
