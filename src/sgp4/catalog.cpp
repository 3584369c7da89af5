// Catalog issues (see catalog.hpp).
#include "evade/sgp4/catalog.hpp"

#include "evade/sgp4/text_fields.hpp"

namespace evade::sgp4 {

// Printable UTF-8 whatever the file held: the found text is the file's own bytes (a Latin-1
// byte in a field made `evade propagate --tle --json` write invalid JSON).
std::string ReadIssue::message() const {
  std::string m = source + ":" + std::to_string(line);
  if (column > 0) m += ":" + std::to_string(column);
  return printable_utf8(m + ": expected " + expected + ", found '" + found + "'");
}

}  // namespace evade::sgp4
