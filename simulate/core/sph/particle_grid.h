#pragma once
// A particle set sorted into a UniformGrid: keys, stable sort, cell ranges.
#include <algorithm>
#include <cstdint>
#include <optional>

#include "sph/uniform_grid.h"

namespace dp {

template <class Exec>
struct ParticleGrid {
  UniformGrid grid;
  typename Exec::template Buffer<std::uint32_t> key, order;
  // cell_count() + 1 entries: cell c holds sorted particles cell_begin[c] ..
  // cell_begin[c + 1] - 1 (CellBegins).
  typename Exec::template Buffer<std::uint32_t> cell_begin;

  // Sorts positions into the grid; `order[i]` is then the unsorted index of
  // the i-th sorted particle, for the caller to gather its attributes.
  void sort(const Exec& exec, const typename Exec::template Buffer<Vec3>& position) {
    std::size_t n = position.size();
    key.resize(n);
    order.resize(n);
    exec.parallel_for(n, ComputeCellKeys{grid, Exec::ptr(position), Exec::ptr(key), Exec::ptr(order)});
    exec.sort_by_key(key, order);
  }

  // Cell ranges of the sorted keys. Green (2009) finds only non-empty
  // cells' ranges; here empty cells have one too, which lets a query walk a
  // row of cells as one run. Where the host reads the keys for free (the
  // CPU backend), only cells whose begin can have changed since the last
  // call are written: each entry depends on the sorted keys alone, every
  // cell up to the lowest key begins at 0 and every cell past the highest
  // at n. For a small liquid body in a large domain (the Drop: 1.2K
  // particles, 2.2M cells) that is a few slabs of cells instead of all.
  void find_ranges(const Exec& exec) {
    const std::uint32_t cells = grid.cell_count();
    const std::uint32_t n = static_cast<std::uint32_t>(key.size());
    if (cell_begin.size() != std::size_t{cells} + 1) {
      cell_begin.resize(std::size_t{cells} + 1);
      written_.reset();
    }
    CellSpan span{0, cells};
    if constexpr (Exec::kBuffersInHostMemory) span = cells_to_rewrite(cells, n);
    exec.parallel_for(std::size_t{span.last} - span.first + 1,
                      CellBegins{Exec::ptr(key), n, Exec::ptr(cell_begin), span.first});
  }

  GridView view(const typename Exec::template Buffer<Vec3>& sorted_position) const {
    return GridView{grid, Exec::ptr(cell_begin), Exec::ptr(cell_begin) + 1, Exec::ptr(sorted_position)};
  }

 private:
  struct CellSpan {
    std::uint32_t first, last;  // inclusive
  };
  // The sorted keys at the last find_ranges: cells up to `lowest` began at
  // 0, cells past `highest` at `count`. No keys: every cell began at 0.
  struct KeyExtent {
    std::uint32_t lowest, highest, count;
  };
  std::optional<KeyExtent> written_;

  CellSpan cells_to_rewrite(std::uint32_t cells, std::uint32_t n) {
    const KeyExtent now = n ? KeyExtent{key[0], key[n - 1], n} : KeyExtent{cells, cells, 0};
    CellSpan span{0, cells};
    if (written_) {
      span.first = std::min(written_->lowest, now.lowest);
      if (written_->count == now.count) span.last = std::max(written_->highest, now.highest);
    }
    written_ = now;
    return span;
  }
};

// out[i] = in[order[i]]
template <class T>
struct Gather {
  const std::uint32_t* order;
  const T* in;
  T* out;
  DP_HD void operator()(std::size_t i) const { out[i] = in[order[i]]; }
};

}  // namespace dp
