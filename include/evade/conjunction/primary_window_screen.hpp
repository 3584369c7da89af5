// One satellite against a catalog, screened only where it can be close (issue 24): the
// objects left by the perigee/apogee filter (primary_prefilter.hpp) go through the time
// filter (primary_time_filter.hpp); each window of each object is then screened with the
// primary by the robust screener (robust_screen.hpp) on the SGP4 motion of the two over
// that window alone, its perturbation envelope sampled over the window (sgp4_motion.hpp; the
// same sampling density as over a whole span, so the same assumption S1). Objects run on
// threads (object k on thread k mod threads); results do not depend on the split.
#pragma once

#include <string>
#include <vector>

#include "evade/conjunction/primary_time_filter.hpp"
#include "evade/conjunction/robust_screen.hpp"
#include "evade/conjunction/sgp4_motion.hpp"

namespace evade::conjunction {

/// What the time filter and the window screens did.
struct TimeFilterCounts {
  long objects = 0;         ///< objects against the primary (after the perigee/apogee filter)
  long removed = 0;         ///< never within D: no window
  long screened = 0;        ///< with at least one window (the unfiltered included)
  long unfiltered = 0;      ///< screened over the whole span (PrimaryWindows::unfiltered)
  long windows = 0;         ///< merged windows screened
  double window_s = 0.0;    ///< their total length [s]
  long evaluations = 0;     ///< SGP4 pair evaluations of the filter
};

struct PrimaryWindowScreen {
  /// The primary and the objects screened against it, states only (envelopes = false), in
  /// the order of the element sets; element sets rejected by a window's screen are left out.
  Sgp4Screening screening;
  ScreenResult result;      ///< events indexed into screening.objects; the windows' stats summed
  double step_s = 0.0;      ///< the windows' grid step [s] (screen.step_s, or auto_step_s)
  TimeFilterCounts counts;
};

/// Index of the object with NORAD `norad` in s. Throws std::invalid_argument naming
/// "--primary N" when it was rejected (with the reason) or is not in the catalog.
std::size_t primary_index(const Sgp4Screening& s, long norad);

/// Screens the element set with NORAD primary_norad against the others of `elements` over
/// [start, start + span_s] (start: UTC s since J2000), pairs with the primary only.
/// `screen` gives the threshold, grid step (0: auto_step_s of the objects), leaf, threads
/// and progress; motion, gravity, earth and primary are set here. Throws
/// std::invalid_argument when the primary is missing or rejected (over the whole span).
PrimaryWindowScreen screen_primary_windows(const std::vector<sgp4::MeanElements>& elements,
                                           long primary_norad, double start_j2000_s,
                                           double span_s, const ScreenOptions& screen,
                                           const TimeFilterOptions& filter);

}  // namespace evade::conjunction
