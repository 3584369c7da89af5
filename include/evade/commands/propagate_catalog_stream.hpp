// `evade propagate --tle/--omm` written as it goes: every object of a catalog propagated with
// SGP4 (Vallado, Crawford, Hujsak and Kelso, "Revisiting Spacetrack Report #3", 2006) over
// the same instants as run_propagate_catalog (propagate_catalog_command.hpp), the states
// formatted and handed to a sink in order while the next ones are computed. Memory does not
// depend on the number of time steps or objects beyond one summary per object: the work is
// cut into tasks of at most kStreamChunkSteps instants of one object; `threads` workers
// compute and format one wave of tasks into their own reused buffers, then the buffers go
// to the sink in catalog and time order. An object stops at its first SGP4 error, as in the
// in-memory call (tasks after it in the same object are dropped).
//
// Formats:
//  - kJson: one JSON document, the same keys as to_json(PropagateCatalogResult) (its states
//    streamed one per line, "sgp4_error" after "states"), numbers in shortest round-trip form;
//  - kCsv: a header `id,t_s,<frame>_x_m,…,<frame>_vz_mps` (frame teme or j2000) and one row per
//    state; the SGP4 errors are in the summaries (the CLI prints them on stderr);
//  - kNone: nothing is written (the summaries only, for the text output).
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "evade/commands/propagate_catalog_command.hpp"

namespace evade::commands {

enum class StateFormat { kNone, kJson, kCsv };

/// Instants of one object per task.
constexpr long kStreamChunkSteps = 2048;

/// One object after the stream: its track without the states, the count and the last one.
struct StreamedTrack {
  long id = 0;
  std::string name;
  double epoch_j2000_s = 0.0;
  long states = 0;             ///< instants written
  CatalogState last;           ///< the last written (when states > 0)
  sgp4::Sgp4Error error = sgp4::Sgp4Error::kNone;
  double error_t_s = 0.0;
};

struct StreamedCatalog {
  double start_j2000_s = 0.0;
  bool j2000 = false;
  int bad_entries = 0;
  std::vector<std::string> issues;
  std::vector<StreamedTrack> objects;  ///< catalog order
  long states = 0;                     ///< total written
};

/// Bytes ready for the output, in order.
using ByteSink = std::function<void(const char* data, std::size_t size)>;

/// Propagates every valid object and writes as it goes (see above); threads <= 0: the
/// hardware's. Throws std::invalid_argument as run_propagate_catalog does.
StreamedCatalog stream_propagate_catalog(const PropagateCatalogRequest& req, StateFormat format,
                                         int threads, const ByteSink& sink);

/// The text `evade propagate --tle/--omm` prints: one line per object with its last state.
std::string to_text(const StreamedCatalog& r);

}  // namespace evade::commands
