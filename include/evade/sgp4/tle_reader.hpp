// Two-line element sets (TLE) and three-line sets (3LE: a title line, "0 NAME" or "NAME",
// before each pair), in the fixed-column format of the Space-Track / NORAD two-line element
// definition: column ranges, Alpha-5 catalog numbers, implied-decimal exponent fields and
// the modulo-10 checksum (digits plus 1 for each '-', over columns 1-68).
#pragma once

#include <string>

#include "evade/sgp4/catalog.hpp"
#include "evade/sgp4/mean_elements.hpp"

namespace evade::sgp4 {

struct TleReadOptions {
  /// Verify column 69. Off only for files known to carry wrong checksums (the published
  /// SGP4 verification set has three deliberate error cases with bad ones).
  bool check_checksum = true;
  /// Accept text after column 69 of line 2 (the verification set keeps its start, stop and
  /// step times there); normally columns 70+ must be blank.
  bool allow_trailing_text = false;
};

/// Parses one element set; throws ReadError naming the line and column of the first fault.
/// line1_no is the 1-based line number of line1 in its source (line2 is the next one).
MeanElements parse_tle(const std::string& line1, const std::string& line2, const std::string& name,
                       const std::string& source, int line1_no,
                       const TleReadOptions& opt = TleReadOptions{});

/// Reads a TLE or 3LE file's text. Blank lines and lines starting with '#' are skipped.
/// A bad entry is recorded in Catalog::issues and the reading goes on with the next one.
Catalog read_tle(const std::string& text, const std::string& source,
                 const TleReadOptions& opt = TleReadOptions{});

/// The checksum digit of a line (columns 1-68).
int tle_checksum(const std::string& line) noexcept;

}  // namespace evade::sgp4
