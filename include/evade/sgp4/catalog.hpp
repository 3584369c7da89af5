// A catalog read from text: the entries that passed every check, and one issue per rejected
// entry (source, line, column, what was expected, what was found), so a reader never stops
// at the first bad entry and never drops one silently. The TLE reader is tle_reader.hpp; the
// CCSDS OMM and "GP" forms, and the reader of any of them, are evade/ccsds/catalog_formats.hpp.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "evade/sgp4/mean_elements.hpp"

namespace evade::sgp4 {

struct ReadIssue {
  std::string source;    ///< file name (as the caller named it)
  int line = 0;          ///< 1-based
  int column = 0;        ///< 1-based; 0 when the issue is not tied to a column
  std::string expected;  ///< what the format requires there
  std::string found;     ///< what the text holds there

  /// "FILE:LINE:COL: expected EXPECTED, found 'FOUND'".
  std::string message() const;
};

struct Catalog {
  std::vector<MeanElements> objects;
  std::vector<ReadIssue> issues;  ///< one per rejected entry
  int bad_entries = 0;            ///< entries rejected (== issues.size())
};

/// Thrown by the single-entry parsers; the catalog readers catch it and record the issue.
/// A std::runtime_error whose what() is issue.message(), so a caller that catches
/// std::exception (the CLI, the Python module) reports it too.
struct ReadError : std::runtime_error {
  explicit ReadError(ReadIssue i) : std::runtime_error(i.message()), issue(std::move(i)) {}
  ReadIssue issue;
};

}  // namespace evade::sgp4
