// What the in-memory and the streamed `evade propagate --tle/--omm` share (private to the
// sgp4 module): the checked request's header, the output instants and the state at one of
// them, and the UTC text of an instant.
#pragma once

#include <string>

#include "evade/commands/propagate_catalog_command.hpp"

namespace evade::commands::detail {

/// The result without its objects: the request checked (check_propagate_catalog_request, and
/// std::invalid_argument "no valid element set in the file (N bad entries)" for an empty
/// catalog), the start (the latest element epoch), the frame and the reader's issues.
PropagateCatalogResult catalog_result_header(const PropagateCatalogRequest& req);

/// The output instants are k = 0..last_instant(req), at instant_s(req, k) from the start.
long last_instant(const PropagateCatalogRequest& req);
double instant_s(const PropagateCatalogRequest& req, long k);

/// The state at t_s from the start (start_j2000_s) of an object whose element epoch is
/// offset_s before the start, in TEME or J2000; the SGP4 error (kNone: *out written).
sgp4::Sgp4Error catalog_state(const sgp4::Sgp4Propagator& p, double offset_s, double start_j2000_s,
                        double t_s, bool j2000, CatalogState* out);

/// "YYYY-MM-DD hh:mm:ss.fffffffff" of UTC seconds since J2000.
std::string utc_text(double j2000_s);

}  // namespace evade::commands::detail
