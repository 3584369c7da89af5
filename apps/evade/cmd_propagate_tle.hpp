// `evade propagate --tle FILE | --omm FILE`: the catalog path of `evade propagate`
// (cmd_propagate.cpp registers the flags and hands over here).
#pragma once

#include <string>

namespace evade::cli {

struct CatalogPropagateOptions {
  std::string tle_path;   ///< --tle: TLE or 3LE text
  std::string omm_path;   ///< --omm: OMM KVN or XML, or GP JSON or CSV (detected from the text)
  double span_s = 86400.0;
  double step_s = 60.0;
  std::string frame = "teme";  ///< teme | eci (J2000)
  bool json = false;
};

/// Reads the catalog, propagates every object with SGP4 and prints the states. Exit 0 when
/// at least one entry was read (bad entries are listed on stderr and in the JSON), 2 when
/// the file has no valid entry or a flag is out of range (std::invalid_argument).
int run_propagate_catalog(const CatalogPropagateOptions& o);

}  // namespace evade::cli
