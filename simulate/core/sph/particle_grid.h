#pragma once
// A particle set sorted into a UniformGrid: keys, stable sort, cell ranges.
#include <cstdint>

#include "sph/uniform_grid.h"

namespace dp {

template <class Exec>
struct ParticleGrid {
  UniformGrid grid;
  typename Exec::template Buffer<std::uint32_t> key, order, cell_count, cell_begin, cell_end;

  // Sorts positions into the grid; `order[i]` is then the unsorted index of
  // the i-th sorted particle, for the caller to gather its attributes.
  void sort(const Exec& exec, const typename Exec::template Buffer<Vec3>& position) {
    std::size_t n = position.size();
    key.resize(n);
    order.resize(n);
    exec.parallel_for(n, ComputeCellKeys{grid, Exec::ptr(position), Exec::ptr(key), Exec::ptr(order)});
    exec.sort_by_key(key, order);
  }

  // Cell ranges of the sorted keys, by count and exclusive scan (Green 2009
  // finds only non-empty cells' ranges; the scan gives empty cells a range
  // too, which lets a query walk a row of cells as one run).
  void find_ranges(const Exec& exec) {
    cell_count.resize(grid.cell_count());
    exec.parallel_for(grid.cell_count(), ClearCounts{Exec::ptr(cell_count)});
    exec.parallel_for(key.size(), CountPerCell{Exec::ptr(key), key.size(), Exec::ptr(cell_count)});
    exec.exclusive_scan(cell_count, cell_begin);
    cell_end.resize(grid.cell_count());
    exec.parallel_for(grid.cell_count(), CellEnds{Exec::ptr(cell_begin), Exec::ptr(cell_count), Exec::ptr(cell_end)});
  }

  GridView view(const typename Exec::template Buffer<Vec3>& sorted_position) const {
    return GridView{grid, Exec::ptr(cell_begin), Exec::ptr(cell_end), Exec::ptr(sorted_position)};
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
