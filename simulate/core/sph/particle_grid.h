#pragma once
// A particle set sorted into a UniformGrid: keys, stable sort, cell ranges.
#include <cstdint>

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
  // row of cells as one run.
  void find_ranges(const Exec& exec) {
    const std::size_t cells = grid.cell_count();
    cell_begin.resize(cells + 1);
    exec.parallel_for(cells + 1, CellBegins{Exec::ptr(key), static_cast<std::uint32_t>(key.size()), Exec::ptr(cell_begin)});
  }

  GridView view(const typename Exec::template Buffer<Vec3>& sorted_position) const {
    return GridView{grid, Exec::ptr(cell_begin), Exec::ptr(cell_begin) + 1, Exec::ptr(sorted_position)};
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
