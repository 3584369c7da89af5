// The catalog formats `evade propagate --tle/--omm` and `evade screen --tle/--omm` read, and
// the reader of any of them: TLE/3LE (sgp4/tle_reader.hpp), CCSDS OMM (502.0-B-2) in KVN
// (omm_kvn.hpp) and XML (omm_xml.hpp), and the JSON and CSV "GP" forms catalogue providers
// serve with the OMM keywords (gp_json.hpp, gp_csv.hpp). Every form gives a sgp4::Catalog:
// the element sets that passed every check and one issue per rejected entry.
#pragma once

#include <string>

#include "evade/sgp4/catalog.hpp"

namespace evade::ccsds {

/// Text of the catalog formats the readers understand.
enum class CatalogFormat { kTle, kOmmKvn, kOmmXml, kGpJson, kGpCsv };

/// Guesses the format from the first non-blank character and line: '<' XML, '[' or '{'
/// JSON, "CCSDS_OMM_VERS" KVN, a CSV header naming OBJECT_NAME or NORAD_CAT_ID, else TLE.
CatalogFormat detect_catalog_format(const std::string& text);

/// Reads text in any of the formats above.
sgp4::Catalog read_catalog(const std::string& text, const std::string& source);

}  // namespace evade::ccsds
