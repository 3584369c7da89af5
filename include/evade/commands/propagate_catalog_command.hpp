// `evade propagate --tle FILE | --omm FILE` as a library call: every object of a catalog
// propagated with SGP4 (Vallado, Crawford, Hujsak and Kelso, "Revisiting Spacetrack Report
// #3", 2006; improved operation mode) over the same instants, in TEME or in J2000
// (teme_to_j2000.hpp). Times: t_s counts from the latest element epoch in the catalog
// (start_utc), so every object is propagated over the same instants.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "evade/sgp4/catalog.hpp"
#include "evade/sgp4/sgp4.hpp"

namespace evade::commands {

struct PropagateCatalogRequest {
  sgp4::Catalog catalog;       ///< read by the caller (ccsds::read_catalog), bad entries included
  double span_s = 86400.0;     ///< time span from the latest element epoch [s]
  double step_s = 60.0;        ///< output step [s]
  std::string frame = "teme";  ///< teme | eci (J2000)
};

/// Checks span_s, step_s and frame (not the catalog); std::invalid_argument naming the flag
/// (--span-s, --step-s, --frame), the value and what is allowed.
void check_propagate_catalog_request(const PropagateCatalogRequest& req);

/// One output instant of one object.
struct CatalogState {
  double t_s = 0.0;                                ///< from start_utc [s]
  Eigen::Vector3d r_m = Eigen::Vector3d::Zero();   ///< position in the result's frame [m]
  Eigen::Vector3d v_mps = Eigen::Vector3d::Zero(); ///< velocity in the result's frame [m/s]
};

struct CatalogTrack {
  long id = 0;                   ///< NORAD catalog number
  std::string name;
  double epoch_j2000_s = 0.0;    ///< element epoch, UTC seconds since J2000
  std::vector<CatalogState> states;
  sgp4::Sgp4Error error = sgp4::Sgp4Error::kNone;  ///< why SGP4 stopped (kNone: every instant computed)
  double error_t_s = 0.0;              ///< the instant SGP4 stopped at [s]
};

struct PropagateCatalogResult {
  double start_j2000_s = 0.0;   ///< latest element epoch, UTC seconds since J2000
  bool j2000 = false;           ///< frame of the states: J2000 (true) or TEME (false)
  int bad_entries = 0;          ///< catalog entries rejected by the reader
  std::vector<std::string> issues;  ///< one message per rejected entry
  std::vector<CatalogTrack> objects;
};

/// Propagates every valid object. Throws std::invalid_argument for a bad span, step or frame,
/// or when the catalog has no valid entry ("no valid element set in the file (N bad
/// entries)").
PropagateCatalogResult run_propagate_catalog(const PropagateCatalogRequest& req);

/// The JSON document of the result: the one `evade propagate --tle/--omm --json` streams
/// (propagate_catalog_stream.hpp, which also gives the text form).
nlohmann::json to_json(const PropagateCatalogResult& r);

}  // namespace evade::commands
