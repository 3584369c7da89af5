// Internal (not installed): the robust screener's broad phase on one grid step
// (src/conjunction/box_grid.cpp): every object's swept box, padded by g h^2/8 + D/2, in a
// uniform grid whose cells are as large as the largest box (each box touches at most 2 cells
// per axis, so at most 8 cells), and the (cell, object) entries sorted by cell by a radix
// sort, each cell's objects in increasing order (robust_screen.hpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "evade/core/state.hpp"

namespace evade::conjunction::internal {

// One object's box and lowest cell (relative to the origin), in one cache line.
struct alignas(64) GridBox {
  double lo[3];
  double hi[3];
  std::int32_t cell[3];
};

/// Cells per axis of the grid at most (plus one): cells are at least the boxes' extent / this,
/// so a cell key stays below 1202^3 < 2^31 and fits the entries' layout whatever the boxes.
constexpr double kMaxCellsPerAxis = 1200.0;

// The swept boxes of one grid step in a uniform grid of cells as large as the largest box
// (each box touches at most 2 cells per axis) and at least the extent / kMaxCellsPerAxis:
// for each object its box and its lowest cell, and the (cell, object) entries sorted by cell.
struct BoxGrid {
  double cell_m = 0.0;
  std::int64_t origin[3] = {0, 0, 0};  // lowest cell on each axis
  std::int64_t extent[3] = {1, 1, 1};  // cells on each axis
  std::vector<Vec3> lo, hi;
  std::vector<GridBox> box;
  std::vector<std::uint64_t> entries, scratch;

  std::uint64_t key(std::int64_t x, std::int64_t y, std::int64_t z) const {
    return static_cast<std::uint64_t>((x * extent[1] + y) * extent[2] + z);
  }

  /// Sorts the boxes lo[0 .. n), hi[0 .. n) into the grid: cell_m, origin, extent, box and
  /// entries ((cell key << 32 | object), sorted by cell).
  void build(std::size_t n);
};

}  // namespace evade::conjunction::internal
