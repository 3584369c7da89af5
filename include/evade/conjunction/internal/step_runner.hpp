// Internal (not installed): the robust screener's step runner
// (src/conjunction/step_runner.cpp): the grid steps of a screening (or of one part of it,
// screen_robust_part) by blocks, on std::thread workers (screen_worker.hpp).
#pragma once

#include <algorithm>
#include <vector>

#include "evade/conjunction/ephemeris.hpp"
#include "evade/conjunction/internal/screen_support.hpp"
#include "evade/conjunction/internal/screen_worker.hpp"
#include "evade/conjunction/robust_screen.hpp"

namespace evade::conjunction::internal {

// The grid steps [k_begin, k_end) of a screening, by blocks of grid steps: the threads first
// advance every object (split by objects) through the block's grid times, then screen the
// block's steps (split by steps). Each object's integrator visits every grid time from
// t = 0 (J2), so its states, and therefore every event, do not depend on how the steps are
// split between threads or processes.
class StepRunner {
 public:
  StepRunner(const std::vector<SpaceObject>& objects, const std::vector<ObjectBounds>& bounds,
             const ScreenOptions& opt, double span_s, long nsteps, int nthreads);

  // Screens the grid steps [k_begin, k_end); appends the events and adds the statistics.
  void run(long k_begin, long k_end, ScreenResult& res);

 private:
  double grid_time(long k) const {
    return k >= nsteps_ ? span_s_ : std::min(static_cast<double>(k) * opt_.step_s, span_s_);
  }

  // Every object through grid times k_from .. k_to; the states at grid time k go to
  // rows_[k - k_row0] when k >= k_row0 (objects split between threads in chunks).
  void advance(long k_from, long k_to, long k_row0);

  // Grid steps [k0, k1) from rows_[0 .. k1 - k0] (steps split between threads).
  void screen_steps(long k0, long k1);

  const std::vector<SpaceObject>& objects_;
  const ScreenOptions& opt_;
  double span_s_;
  long nsteps_;
  int nthreads_;
  Ephemeris eph_;
  std::vector<Worker> workers_;
  std::vector<std::vector<StateEci>> rows_;
};

}  // namespace evade::conjunction::internal
