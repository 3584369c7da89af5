// The CSV "GP" form catalogue providers serve: a header row of OMM keywords, then one row
// per object (RFC 4180 quoting).
#pragma once

#include <string>

#include "evade/sgp4/catalog.hpp"

namespace evade::ccsds {

/// Reads every row; a bad row is rejected with its line and the column of the bad field.
/// Header names that are not OMM keywords are ignored, like the JSON form's extra keys.
sgp4::Catalog read_gp_csv(const std::string& text, const std::string& source);

}  // namespace evade::ccsds
