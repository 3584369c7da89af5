// SGP4 of N catalog objects at T arbitrary instants, into caller-owned arrays: the call under
// the Python `evade.sgp4.propagate(catalog, start_utc, t_s, frame, threads)` (docs/PYTHON.md)
// and for C++ callers that want the states without the command's JSON. SGP4 is Vallado,
// Crawford, Hujsak and Kelso, "Revisiting Spacetrack Report #3" (2006), improved mode, as in
// propagate_catalog_command.hpp; the J2000 frame is teme_to_j2000.hpp's.
//
// Unlike `evade propagate`, whose instants are a regular grid and whose track stops at the
// first SGP4 error, every (object, instant) here is evaluated on its own: the instants may be
// in any order, and an error at one instant (decay, eccentricity out of range) is reported
// there, with NaN states (decay keeps the state the theory computed), as python sgp4's
// SatrecArray does. The states come from the four-lane path where the processor has it
// (sgp4_x4_vectorized(): propagate_x4, within kSgp4X4PositionErrorRel |r| of propagate_s
// near Earth and kSgp4X4DeepPositionErrorRel |r| in deep space), else from propagate_s; the
// error codes are always propagate_s's.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "evade/sgp4/catalog.hpp"

namespace evade::sgp4 {

/// The start of a propagation: an ISO 8601 UTC text ("YYYY-MM-DDThh:mm:ss[.fff][Z]", a space
/// for the T also accepted), or empty for the latest element epoch of the catalog.
/// std::invalid_argument naming the text when it cannot be read.
double start_j2000_s_from_utc(const std::string& start_utc, const Catalog& catalog);

/// Where the states go: n_objects x n_times x 3 doubles each (C order: object, instant,
/// component) and n_objects x n_times error codes (Sgp4Error as int32; 0 = computed).
struct StateGridOut {
  double* r_m = nullptr;       ///< position in the chosen frame [m]; NaN at an error other than decay
  double* v_mps = nullptr;     ///< velocity in the chosen frame [m/s]; NaN likewise; nullptr: positions only
  std::int32_t* error = nullptr;
};

struct StateGridRequest {
  double start_j2000_s = 0.0;  ///< t = 0 of t_s, UTC seconds since J2000
  const double* t_s = nullptr; ///< the instants, seconds after the start (any order)
  std::size_t n_times = 0;
  bool j2000 = false;          ///< frame: J2000 (true) or TEME (false)
  int threads = 0;             ///< worker threads; 0: hardware concurrency
};

/// Checks the request (a catalog with a valid entry: "no valid element set in the file (N bad
/// entries)" as `evade propagate` says; finite start and instants; at most 1e9 states; threads)
/// before any work; std::invalid_argument naming what is wrong.
void check_state_grid_request(const Catalog& catalog, const StateGridRequest& req);

/// Propagates catalog.objects (in catalog order) at every instant into out, which must hold
/// catalog.objects.size() * req.n_times states. Throws what check_state_grid_request throws.
void propagate_grid(const Catalog& catalog, const StateGridRequest& req, const StateGridOut& out);

/// "teme" -> false, "eci" (J2000) -> true, as `evade propagate --frame`; std::invalid_argument
/// ("--frame = 'x' is invalid: expected teme or eci") otherwise.
bool frame_is_j2000(const std::string& frame);

}  // namespace evade::sgp4
