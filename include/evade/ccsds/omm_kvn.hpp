// CCSDS OMM in keyword = value notation (502.0-B-2 section 4 and 7: "KEY = value [unit]",
// COMMENT lines, one message per CCSDS_OMM_VERS header; a file may hold several messages).
#pragma once

#include <string>

#include "evade/sgp4/catalog.hpp"

namespace evade::ccsds {

/// Reads every OMM of a KVN text. A bad line or value rejects its message (recorded with
/// line and column) and reading goes on at the next CCSDS_OMM_VERS.
sgp4::Catalog read_omm_kvn(const std::string& text, const std::string& source);

}  // namespace evade::ccsds
