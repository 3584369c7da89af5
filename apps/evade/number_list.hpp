// Lists of numbers given on the command line ("500,20,80,40,10", "A:B:N"), read field by field
// with strtod, so that a malformed field is an error and never a partial value (sscanf reports
// no conversion errors).
#pragma once

#include <string>
#include <vector>

namespace evade::cli {

/// The numbers of `text` separated by `sep`: each field is exactly one number as strtod reads
/// it (leading blanks allowed; nothing after it, not empty, not beyond the range of double).
/// Empty when any field is not such a number.
std::vector<double> parse_number_list(const std::string& text, char sep);

}  // namespace evade::cli
