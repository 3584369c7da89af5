// `evade screen --tle FILE | --omm FILE`: the catalog path of `evade screen` (cmd_screen.cpp
// registers the flags and hands over here): reads the file, calls
// commands::run_screen_catalog (every object moves by SGP4), writes the CDMs and prints.
#pragma once

#include <string>
#include <vector>

#include "screen_cdm_out.hpp"

namespace evade::cli {

struct CatalogScreenOptions {
  std::string tle_path;      ///< --tle: TLE or 3LE text
  std::string omm_path;      ///< --omm: OMM KVN/XML or GP JSON/CSV (detected from the text)
  long primary_norad = -1;   ///< --primary: screen this object against the catalog
  /// --span-s, --threshold-m, --step-s, typed (evade/config/param_flags.hpp)
  std::vector<ParamValue> param_values;
  std::string start_utc;     ///< --start (empty: the latest element epoch)
  int threads = 0;           ///< 0: hardware concurrency
  bool no_prefilter = false; ///< --no-prefilter: with --primary, propagate every object
  bool no_time_filter = false; ///< --no-time-filter: with --primary, screen the whole span
  bool no_path_filter = false; ///< --no-path-filter: with --primary, no orbit-path filter
  bool json = false;
  bool quiet = false;
  CdmOutOptions cdm;         ///< --cdm-out DIR ...: one CDM per event
};

/// Reads the catalog, screens it with SGP4 motion and prints the events. Exit 0 when at
/// least one pair could be screened (bad entries and rejected element sets are listed on
/// stderr and in the JSON); std::invalid_argument (exit 2) for bad flags, an unknown
/// --primary or a file with no usable element set.
int run_catalog_screen(const CatalogScreenOptions& o);

}  // namespace evade::cli
