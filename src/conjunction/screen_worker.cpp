// The robust screener's worker (issue 6; internal/screen_worker.hpp): one grid step at a
// time, the arc bounds of every object (under J2 the arc lemma of arc_bounds.hpp, proved in
// docs/VALIDATION.md; under two-body the conic's radius range, set once), the swept boxes in
// the grid, the pairs of each cell (box overlap tested branch-free, each pair kept in the
// cell that holds the low corner of the overlap, the apogee/perigee filter of Hoots,
// Crawford & Roehrich, Celest. Mech. 33, 1984, on the step's radius ranges) and the narrow
// phase. The reporting distance D_ij = max(D, N R_c) uses R_c of eq. 1 of Wang Xiaoyu,
// "Space entity collision prediction algorithm and self-adaptive simulation step design",
// J. Air Force Eng. Univ. 7(6), 2006 (paper 002).
#include "evade/conjunction/internal/screen_worker.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "evade/conjunction/internal/narrow_phase.hpp"

namespace evade::conjunction::internal {
namespace {

bool apogee_perigee_may_meet(const ArcBounds& a, const ArcBounds& b, double d) {
  return std::max(a.r_lo_m, b.r_lo_m) - std::min(a.r_hi_m, b.r_hi_m) <= d;
}

}  // namespace

Worker::Worker(const std::vector<SpaceObject>& objects_in, const ScreenOptions& opt_in,
               const Ephemeris& eph_in, double d_max_in, std::vector<ArcBounds> conic_bounds,
               std::vector<double> object_size_m)
    : objects(&objects_in),
      opt(&opt_in),
      eph(&eph_in),
      d_max(d_max_in),
      arcs(eph_in.make_arcs()),
      step_bounds(std::move(conic_bounds)),
      size_m(std::move(object_size_m)) {
  if (eph->has_grid_states()) {
    for (ExactStates& c : exact_states) {
      c.state.resize(step_bounds.size());
      c.step.assign(step_bounds.size(), -1);
    }
  }
}

void Worker::update_step_bounds(const StateEci* sa, const StateEci* sb, double dt) {
  if (opt->gravity != GravityModel::kTwoBodyJ2) return;  // conic bounds, set once
  for (std::size_t i = 0; i < step_bounds.size(); ++i) {
    const PerturbationBound pb = opt->motion ? opt->motion->perturbation(i) : PerturbationBound{};
    step_bounds[i] = arc_bounds(sa[i], sb[i], dt, opt->gravity, opt->earth, pb.accel_mps2,
                                eph->grid_velocity_error_mps(i), eph->grid_position_error_m(i));
    step_bounds[i].perturbation_rate_mps3 = pb.rate_mps3;
  }
}

void Worker::build_boxes(const StateEci* sa, const StateEci* sb, double dt) {
  const std::size_t n = step_bounds.size();
  grid.lo.resize(n);
  grid.hi.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    // The arc within G h^2 / 8 of the exact chord, which is within the grid positions' error
    // of this one.
    const double pad =
        step_bounds[i].g_max_mps2 * dt * dt / 8.0 + eph->grid_position_error_m(i) + 0.5 * d_max;
    grid.lo[i] = sa[i].r_eci_m.cwiseMin(sb[i].r_eci_m).array() - pad;
    grid.hi[i] = sa[i].r_eci_m.cwiseMax(sb[i].r_eci_m).array() + pad;
  }
  grid.build(n);
}

void Worker::screen_cell(std::uint64_t key, const StateEci* sa, const StateEci* sb, double t_a,
                         double t_b) {
  const auto cz = static_cast<std::int32_t>(key % static_cast<std::uint64_t>(grid.extent[2]));
  const std::uint64_t xy = key / static_cast<std::uint64_t>(grid.extent[2]);
  const auto cy = static_cast<std::int32_t>(xy % static_cast<std::uint64_t>(grid.extent[1]));
  const auto cx = static_cast<std::int32_t>(xy / static_cast<std::uint64_t>(grid.extent[1]));
  const PairContext ctx{objects, &step_bounds, opt};
  const std::size_t m = cell_obj.size();
  const double* lx = cell_box[0].data();
  const double* ly = cell_box[1].data();
  const double* lz = cell_box[2].data();
  const double* hx = cell_box[3].data();
  const double* hy = cell_box[4].data();
  const double* hz = cell_box[5].data();
  overlap.resize(m);
  double* ov = overlap.data();
  using Side = Eigen::Map<const Eigen::ArrayXd>;
  for (std::size_t p = 0; p < m; ++p) {
    stats.pairs_checked += static_cast<long>(m - p - 1);
    // Box overlap of p with every later member: the smallest over the axes of
    // min(hi_p, hi_q) - max(lo_p, lo_q), >= 0 exactly when the boxes overlap (Eigen's packets,
    // so it is vectorized at any optimization level).
    const std::size_t q0 = p + 1;
    const auto len = static_cast<Eigen::Index>(m - q0);
    auto side = [&](const double* lo, const double* hi) {
      return Side(hi + q0, len).min(hi[p]) - Side(lo + q0, len).max(lo[p]);
    };
    Eigen::Map<Eigen::ArrayXd>(ov + q0, len) = side(lx, hx).min(side(ly, hy)).min(side(lz, hz));
    for (std::size_t q = p + 1; q < m; ++q) {
      if (!(ov[q] >= 0.0) || !opt->screens_pair(cell_obj[p], cell_obj[q])) continue;
      if (std::max(cell_low[0][p], cell_low[0][q]) != cx ||
          std::max(cell_low[1][p], cell_low[1][q]) != cy ||
          std::max(cell_low[2][p], cell_low[2][q]) != cz)
        continue;  // counted in the cell that holds the overlap's low corner
      const std::size_t i = cell_obj[p], j = cell_obj[q];  // i < j (cells keep object order)
      const double d_ij = pair_threshold(i, j);
      if (!apogee_perigee_may_meet(step_bounds[i], step_bounds[j], d_ij)) continue;
      ++stats.candidates;
      const StepPositions pos{sa[i].r_eci_m, sa[j].r_eci_m, sb[i].r_eci_m, sb[j].r_eci_m, t_b - t_a};
      // The grid positions' errors move the separation at each end by at most their sum.
      const double d_grid = d_ij + eph->grid_position_error_m(i) + eph->grid_position_error_m(j);
      if (!may_come_within(i, j, pos, d_grid, ctx, stats)) continue;
      const StateEci &ai = exact(i, 0, sa, t_a), &aj = exact(j, 0, sa, t_a);
      const StateEci &bi = exact(i, 1, sb, t_b), &bj = exact(j, 1, sb, t_b);
      narrow_phase(i, j, Endpoint{t_a, ai, aj}, Endpoint{t_b, bi, bj}, ai, aj, t_a, d_ij, ctx,
                   *eph, arcs, events, stats);
    }
  }
}

const StateEci& Worker::exact(std::size_t i, int end, const StateEci* grid_states, double t_s) {
  if (!eph->has_grid_states()) return grid_states[i];
  ExactStates& c = exact_states[static_cast<std::size_t>(end)];  // sized by the constructor
  if (c.step[i] != stats.steps) {
    c.state[i] = eph->exact_state(i, t_s);
    c.step[i] = stats.steps;
  }
  return c.state[i];
}

void Worker::screen_step(const StateEci* sa, const StateEci* sb, double t_a, double t_b) {
  ++stats.steps;
  update_step_bounds(sa, sb, t_b - t_a);
  build_boxes(sa, sb, t_b - t_a);
  const std::vector<std::uint64_t>& e = grid.entries;
  for (std::size_t r0 = 0; r0 < e.size();) {
    const std::uint64_t key = e[r0] >> 32;
    std::size_t r1 = r0 + 1;
    while (r1 < e.size() && (e[r1] >> 32) == key) ++r1;
    if (r1 - r0 > 1) {  // a cell with one box holds no pair
      cell_obj.clear();
      for (auto& c : cell_box) c.clear();
      for (auto& c : cell_low) c.clear();
      for (std::size_t r = r0; r < r1; ++r) {
        const auto i = static_cast<std::uint32_t>(e[r] & 0xffffffffu);
        const GridBox& b = grid.box[i];
        cell_obj.push_back(i);
        for (std::size_t a = 0; a < 3; ++a) {
          cell_box[a].push_back(b.lo[a]);
          cell_box[a + 3].push_back(b.hi[a]);
          cell_low[a].push_back(b.cell[a]);
        }
      }
      screen_cell(key, sa, sb, t_a, t_b);
    }
    r0 = r1;
  }
}

}  // namespace evade::conjunction::internal
