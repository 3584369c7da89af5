// Internal (not installed): one thread's screening of whole grid steps for the robust
// screener (src/conjunction/screen_worker.cpp): the arc bounds of every object on the step,
// the swept boxes in the grid (box_grid.hpp), the pairs of each cell (box overlap, counted
// once, apogee/perigee), and the narrow phase (narrow_phase.hpp) on each candidate pair. Its
// events and statistics accumulate in the worker; step_runner.hpp merges them.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "evade/conjunction/arc_bounds.hpp"
#include "evade/conjunction/ephemeris.hpp"
#include "evade/conjunction/internal/box_grid.hpp"
#include "evade/conjunction/robust_screen.hpp"

namespace evade::conjunction::internal {

// One thread's screening of whole grid steps: arc bounds, boxes, pairs, narrow phase; its
// events and statistics accumulate here.
struct Worker {
  /// Constructed in place (StepRunner: workers_.emplace_back): the grid, the cell arrays,
  /// the events and the statistics start empty.
  Worker(const std::vector<SpaceObject>& objects_in, const ScreenOptions& opt_in,
         const Ephemeris& eph_in, double d_max_in, std::vector<ArcBounds> conic_bounds,
         std::vector<double> object_size_m);

  const std::vector<SpaceObject>* objects = nullptr;
  const ScreenOptions* opt = nullptr;
  const Ephemeris* eph = nullptr;
  double d_max = 0.0;
  StepArcs arcs;
  std::vector<Conjunction> events;
  ScreenStats stats;
  std::vector<ArcBounds> step_bounds;  // conic bounds (two-body), or per step (J2)
  BoxGrid grid;
  std::vector<double> size_m;  // L_i + dR_i of every object (eq. 1)
  // One cell's members and their boxes, one array per coordinate, for the pair loop.
  std::vector<std::uint32_t> cell_obj;
  std::array<std::vector<double>, 6> cell_box;  // lo x, y, z, hi x, y, z
  std::array<std::vector<std::int32_t>, 3> cell_low;  // lowest cell x, y, z
  std::vector<double> overlap;  // smallest overlap of the boxes' sides (>= 0: they overlap) [m]
  // With cheaper grid states (Ephemeris::has_grid_states): the exact states the narrow phase
  // starts from, computed for the objects of candidate pairs only, at the step's start (0)
  // and end (1); step[i] is the step (stats.steps) state[i] belongs to.
  struct ExactStates {
    std::vector<StateEci> state;
    std::vector<long> step;
  };
  std::array<ExactStates, 2> exact_states;
  // The exact state of object i at the step's start (end 0) or end (1): grid_states[i] when
  // the grid states are exact, else Ephemeris::exact_state, once per object and step.
  const StateEci& exact(std::size_t i, int end, const StateEci* grid_states, double t_s);

  // D_ij (pair_threshold_m of robust_screen.hpp), R_c from the per-object sums.
  double pair_threshold(std::size_t i, std::size_t j) const {
    return pair_threshold_m(*opt, size_m[i] + size_m[j]);
  }

  // Arc bounds of every object on [t_a, t_a + dt] (J2: arc lemma; two-body: the conic).
  void update_step_bounds(const StateEci* sa, const StateEci* sb, double dt);

  // Swept boxes of the step, padded by g h^2/8 + D/2, in the grid.
  void build_boxes(const StateEci* sa, const StateEci* sb, double dt);

  // The pairs of one cell: box overlap, counted once (in the cell of the overlap's low
  // corner), apogee/perigee, narrow phase.
  void screen_cell(std::uint64_t key, const StateEci* sa, const StateEci* sb, double t_a,
                   double t_b);

  // Grid step [t_a, t_b] with the states of every object at both ends.
  void screen_step(const StateEci* sa, const StateEci* sb, double t_a, double t_b);
};

}  // namespace evade::conjunction::internal
