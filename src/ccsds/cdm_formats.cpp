// A CDM in either form (see cdm_formats.hpp).
#include "evade/ccsds/cdm_formats.hpp"

#include "evade/ccsds/cdm_kvn.hpp"
#include "evade/ccsds/cdm_xml.hpp"

namespace evade::ccsds {

Cdm read_cdm_text(const std::string& text) {
  const auto p = text.find_first_not_of(" \t\r\n");
  return p != std::string::npos && text[p] == '<' ? read_cdm_xml(text) : read_cdm_kvn(text);
}

}  // namespace evade::ccsds
