// CDM in KVN (keyword = value [unit]) form, CCSDS 508.0-B-1 sec. 4 and 6: read from text
// handed in (no file I/O) and written to text. A keyword goes to its section by the tables of
// cdm.hpp; OBJECT starts an object; a COMMENT line goes to the start of the section of the
// keyword that follows it. Errors (CdmError) name the line and the keyword.
#pragma once

#include <string>

#include "evade/ccsds/cdm.hpp"

namespace evade::ccsds {

/// Parses and validates (validate_cdm). Throws CdmError.
Cdm read_cdm_kvn(const std::string& text);
std::string write_cdm_kvn(const Cdm& cdm);

}  // namespace evade::ccsds
