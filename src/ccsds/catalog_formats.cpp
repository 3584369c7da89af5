// The catalog formats and their dispatch (see catalog_formats.hpp).
#include "evade/ccsds/catalog_formats.hpp"

#include "evade/ccsds/gp_csv.hpp"
#include "evade/ccsds/gp_json.hpp"
#include "evade/ccsds/omm_kvn.hpp"
#include "evade/ccsds/omm_xml.hpp"
#include "evade/sgp4/tle_reader.hpp"

namespace evade::ccsds {

CatalogFormat detect_catalog_format(const std::string& text) {
  const std::size_t b = text.find_first_not_of(" \t\r\n\xEF\xBB\xBF");
  if (b == std::string::npos) return CatalogFormat::kTle;
  if (text[b] == '<') return CatalogFormat::kOmmXml;
  if (text[b] == '[' || text[b] == '{') return CatalogFormat::kGpJson;
  const std::size_t e = text.find('\n', b);
  const std::string first = text.substr(b, e == std::string::npos ? std::string::npos : e - b);
  if (first.find("CCSDS_OMM_VERS") != std::string::npos) return CatalogFormat::kOmmKvn;
  if (first.find(',') != std::string::npos &&
      (first.find("NORAD_CAT_ID") != std::string::npos || first.find("OBJECT_NAME") != std::string::npos))
    return CatalogFormat::kGpCsv;
  return CatalogFormat::kTle;
}

sgp4::Catalog read_catalog(const std::string& text, const std::string& source) {
  switch (detect_catalog_format(text)) {
    case CatalogFormat::kOmmXml: return read_omm_xml(text, source);
    case CatalogFormat::kGpJson: return read_gp_json(text, source);
    case CatalogFormat::kOmmKvn: return read_omm_kvn(text, source);
    case CatalogFormat::kGpCsv: return read_gp_csv(text, source);
    case CatalogFormat::kTle: break;
  }
  return sgp4::read_tle(text, source);
}

}  // namespace evade::ccsds
