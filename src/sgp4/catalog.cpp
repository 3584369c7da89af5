// Catalog issues (see catalog.hpp).
#include "evade/sgp4/catalog.hpp"

namespace evade::sgp4 {

std::string ReadIssue::message() const {
  std::string m = source + ":" + std::to_string(line);
  if (column > 0) m += ":" + std::to_string(column);
  return m + ": expected " + expected + ", found '" + found + "'";
}

}  // namespace evade::sgp4
