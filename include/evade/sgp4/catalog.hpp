// A catalog read from text: the entries that passed every check, and one issue per rejected
// entry (source, line, column, what was expected, what was found), so a reader never stops
// at the first bad entry and never drops one silently.
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

/// Text of the catalog formats the readers understand.
enum class CatalogFormat { kTle, kOmmKvn, kOmmXml, kGpJson, kGpCsv };

/// Guesses the format from the first non-blank character and line: '<' XML, '[' or '{'
/// JSON, "CCSDS_OMM_VERS" KVN, a CSV header naming OBJECT_NAME or NORAD_CAT_ID, else TLE.
CatalogFormat detect_catalog_format(const std::string& text);

/// Reads text in any of the formats above.
Catalog read_catalog(const std::string& text, const std::string& source);

}  // namespace evade::sgp4
