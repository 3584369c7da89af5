// A CCSDS Conjunction Data Message (508.0-B-1) in either of its forms: keyword = value
// (cdm_kvn.hpp) or XML (cdm_xml.hpp), the form told by the text.
#pragma once

#include <string>

#include "evade/ccsds/cdm.hpp"

namespace evade::ccsds {

/// A CDM in KVN or XML form (XML when the first non-blank character is '<'). Throws CdmError.
Cdm read_cdm_text(const std::string& text);

}  // namespace evade::ccsds
