// Internal (not installed): the CDM keyword table the model's accessors share with the
// keyword tables (src/ccsds/cdm_keywords.cpp, cdm.cpp).
#pragma once

#include <string>
#include <vector>

namespace evade::ccsds::internal {

// The covariance section's 45 keywords (CR_R, CT_R, CT_T, ..., CTHR_THR), row by row of the
// lower triangle: keyword r (r + 1) / 2 + k is row r, column k.
const std::vector<std::string>& covariance_keyword_table();

}  // namespace evade::ccsds::internal
