// Broad phase of the robust screener (issue 6): the uniform grid of swept boxes of one grid
// step (internal/box_grid.hpp). Cells are as large as the largest box, and at least 1/1200
// of the boxes' extent so that a cell key fits the entries (a short last grid step's small
// boxes spread from LEO to GEO once overflowed it, and pairs were lost), the same cells at
// every coordinate (floor(x / cell), as x times 1 / cell, clamped); each box goes into the cells it touches, and
// the (cell, object) entries are sorted by cell with a stable LSD radix sort, so that pairs
// can be formed per cell in object order.
#include "evade/conjunction/internal/box_grid.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace evade::conjunction::internal {
namespace {

// Cell of coordinate x in a uniform grid of cells 1 / inv_cell_m wide: floor(x inv_cell_m),
// clamped. Nondecreasing in x, which is all the grid needs: a box [lo, hi] goes into the
// cells from cell_index(lo) to cell_index(hi), so two overlapping boxes share a cell.
std::int64_t cell_index(double x, double inv_cell_m) {
  return static_cast<std::int64_t>(std::clamp(std::floor(x * inv_cell_m), -4e6, 4e6));
}

// Stable LSD radix sort of (cell key << 32 | object) by the key's low `key_bits` bits; the
// entries come in object order, so each cell's objects stay in increasing order (the order
// std::sort of the (key, object) pairs gives).
void radix_sort_by_key(std::vector<std::uint64_t>& v, std::vector<std::uint64_t>& tmp,
                       int key_bits) {
  constexpr int kDigit = 11;
  constexpr std::size_t kBuckets = std::size_t{1} << kDigit;
  tmp.resize(v.size());
  std::vector<std::uint32_t> count(kBuckets);
  for (int shift = 32; shift < 32 + key_bits; shift += kDigit) {
    std::fill(count.begin(), count.end(), 0u);
    for (std::uint64_t e : v) ++count[(e >> shift) & (kBuckets - 1)];
    std::uint32_t sum = 0;
    for (std::uint32_t& c : count) {
      const std::uint32_t n = c;
      c = sum;
      sum += n;
    }
    for (std::uint64_t e : v) tmp[count[(e >> shift) & (kBuckets - 1)]++] = e;
    v.swap(tmp);
  }
}

}  // namespace

void BoxGrid::build(std::size_t n) {
  double cell = 0.0;
  Vec3 lo_min = lo[0], hi_max = hi[0];
  for (std::size_t i = 0; i < n; ++i) {
    cell = std::max(cell, (hi[i] - lo[i]).maxCoeff());
    lo_min = lo_min.cwiseMin(lo[i]);
    hi_max = hi_max.cwiseMax(hi[i]);
  }
  // At most kMaxCellsPerAxis + 1 cells per axis, so that every key is below 1202^3 < 2^31
  // and fits the entries' layout (key << 32 | object); larger cells only pair more boxes.
  cell = std::max(cell, (hi_max - lo_min).maxCoeff() / kMaxCellsPerAxis);
  cell_m = cell;
  const double inv_cell = 1.0 / cell;
  for (int a = 0; a < 3; ++a) {
    origin[a] = cell_index(lo_min[a], inv_cell);
    extent[a] = cell_index(hi_max[a], inv_cell) - origin[a] + 1;
  }
  box.resize(n);
  entries.clear();
  for (std::size_t i = 0; i < n; ++i) {
    std::int64_t c0[3], c1[3];
    GridBox& b = box[i];
    for (int a = 0; a < 3; ++a) {
      c0[a] = cell_index(lo[i][a], inv_cell) - origin[a];
      c1[a] = cell_index(hi[i][a], inv_cell) - origin[a];
      b.lo[a] = lo[i][a];
      b.hi[a] = hi[i][a];
      b.cell[a] = static_cast<std::int32_t>(c0[a]);
    }
    for (std::int64_t x = c0[0]; x <= c1[0]; ++x)
      for (std::int64_t y = c0[1]; y <= c1[1]; ++y)
        for (std::int64_t z = c0[2]; z <= c1[2]; ++z)
          entries.push_back(key(x, y, z) << 32 | static_cast<std::uint64_t>(i));
  }
  const std::uint64_t max_key = key(extent[0] - 1, extent[1] - 1, extent[2] - 1);
  if ((max_key >> 31) != 0) throw std::logic_error("box grid: a cell key above 2^31 (the cell size bound failed)");
  int bits = 1;
  while (bits < 31 && (max_key >> bits) != 0) ++bits;
  radix_sort_by_key(entries, scratch, bits);
}

}  // namespace evade::conjunction::internal
