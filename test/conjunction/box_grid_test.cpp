// The broad phase's uniform grid (internal/box_grid.hpp) whatever the boxes: a cell key must
// fit the entries' layout (cell key << 32 | object), else cells collide and overlapping
// boxes are never paired. Small boxes (a short last grid step: span mod h) spread over a
// large volume (GEO, lunar-distance orbits) once asked for more cells than that layout
// holds; the grid now makes its cells large enough to keep every key below 2^31.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "evade/conjunction/internal/box_grid.hpp"
#include "evade/conjunction/robust_screen.hpp"

namespace evade::conjunction {
namespace {

using internal::BoxGrid;

// The cell of each entry, decoded from its key, lies inside its box's cell range.
void expect_entries_in_their_boxes(const BoxGrid& g, std::size_t n) {
  std::vector<int> entries_of(n, 0);
  for (const std::uint64_t e : g.entries) {
    const std::uint64_t key = e >> 32;
    const auto i = static_cast<std::size_t>(e & 0xffffffffu);
    ASSERT_LT(i, n);
    ++entries_of[i];
    const std::int64_t z = static_cast<std::int64_t>(key % static_cast<std::uint64_t>(g.extent[2]));
    const std::uint64_t xy = key / static_cast<std::uint64_t>(g.extent[2]);
    const std::int64_t y = static_cast<std::int64_t>(xy % static_cast<std::uint64_t>(g.extent[1]));
    const std::int64_t x = static_cast<std::int64_t>(xy / static_cast<std::uint64_t>(g.extent[1]));
    const std::int64_t cell[3] = {x, y, z};
    const double inv_cell = 1.0 / g.cell_m;  // the grid's cells: floor(x / cell) as x (1 / cell)
    for (int a = 0; a < 3; ++a) {
      const auto c0 = static_cast<std::int64_t>(std::floor(g.lo[i][a] * inv_cell)) - g.origin[a];
      const auto c1 = static_cast<std::int64_t>(std::floor(g.hi[i][a] * inv_cell)) - g.origin[a];
      EXPECT_GE(cell[a], c0) << "object " << i << " axis " << a;
      EXPECT_LE(cell[a], c1) << "object " << i << " axis " << a;
    }
  }
  for (std::size_t i = 0; i < n; ++i) EXPECT_GE(entries_of[i], 1) << "object " << i << " in no cell";
}

TEST(BoxGrid, CellKeysFitTheEntryLayoutWhenSmallBoxesSpreadFar) {
  BoxGrid g;
  // Two 10 m boxes that overlap near the origin, one 10 m box at lunar distance on every
  // axis: cells as large as the largest box would need 4e7 cells per axis.
  g.lo = {Vec3(0.0, 0.0, 0.0), Vec3(5.0, 5.0, 5.0), Vec3(4e8, 4e8, 4e8)};
  g.hi = {Vec3(10.0, 10.0, 10.0), Vec3(15.0, 15.0, 15.0), Vec3(4e8 + 10.0, 4e8 + 10.0, 4e8 + 10.0)};
  g.build(3);
  const std::uint64_t max_key = g.key(g.extent[0] - 1, g.extent[1] - 1, g.extent[2] - 1);
  EXPECT_LT(max_key, std::uint64_t{1} << 31);
  EXPECT_GE(g.cell_m, 10.0);  // never smaller than the largest box
  expect_entries_in_their_boxes(g, 3);
  // The overlapping pair shares the cell of its overlap's low corner.
  bool shared = false;
  for (const std::uint64_t e0 : g.entries)
    for (const std::uint64_t e1 : g.entries)
      shared = shared || ((e0 >> 32) == (e1 >> 32) && (e0 & 0xffffffffu) == 0 && (e1 & 0xffffffffu) == 1);
  EXPECT_TRUE(shared);
}

TEST(BoxGrid, CellsAsLargeAsTheLargestBoxWhenTheyFit) {
  BoxGrid g;
  g.lo = {Vec3(0.0, 0.0, 0.0), Vec3(1e6, 0.0, 0.0)};
  g.hi = {Vec3(3e5, 1e5, 1e5), Vec3(1.1e6, 1e5, 1e5)};
  g.build(2);
  EXPECT_EQ(g.cell_m, 3e5);
  expect_entries_in_their_boxes(g, 2);
}

// Circular two-body orbit of radius r in the plane spanned by unit vectors e1, e2, at angle
// n (t - t0) from e1 (so at e1 r at t0), as the state at t = 0.
SpaceObject circular(const char* name, double r_m, const Vec3& e1, const Vec3& e2, double t0_s) {
  const double mu = 3.986004418e14;
  const double n = std::sqrt(mu / (r_m * r_m * r_m)), th = -n * t0_s;
  SpaceObject o;
  o.name = name;
  o.state.r_eci_m = r_m * (std::cos(th) * e1 + std::sin(th) * e2);
  o.state.v_eci_mps = r_m * n * (-std::sin(th) * e1 + std::cos(th) * e2);
  return o;
}

TEST(RobustScreen, FindsACollisionInAShortLastStepBesideAFarObject) {
  // An equatorial and a polar LEO orbit meet at (r, 0, 0) 0.2 s before the span ends, 0.5 s
  // into its last 60 s step; four more objects circle far out on the axes (GEO to lunar
  // distance). The last step's boxes are a few km across, spread over up to 8e8 m.
  const Vec3 x = Vec3::UnitX(), y = Vec3::UnitY(), z = Vec3::UnitZ();
  ScreenOptions opt;
  opt.threshold_m = 5000.0;
  opt.step_s = 60.0;
  opt.threads = 1;
  int missed = 0;
  for (const double far_m : {4.2e7, 1e8, 2e8, 4e8}) {
    for (int k = 5; k <= 12; ++k) {
      const double span_s = 60.0 * k + 0.5, meet_s = span_s - 0.2;
      const std::vector<SpaceObject> objects = {
          circular("equatorial", 7e6, x, y, meet_s), circular("polar", 7e6, x, z, meet_s),
          circular("far y", far_m, y, z, 0.0), circular("far -x", far_m, -x, y, 0.0),
          circular("far z", far_m, z, x, 0.0), circular("far -z", far_m, -z, -y, 0.0)};
      const ScreenResult r = screen_robust(objects, span_s, opt);
      const bool found = r.events.size() == 1 && r.events[0].i == 0 && r.events[0].j == 1 &&
                         std::abs(r.events[0].tca_s - meet_s) < 1e-6 && r.events[0].miss_m < 1e-3;
      missed += found ? 0 : 1;
      EXPECT_TRUE(found) << "far object at " << far_m << " m, span " << span_s << " s: "
                         << r.events.size() << " events";
    }
  }
  EXPECT_EQ(missed, 0);
}

}  // namespace
}  // namespace evade::conjunction
