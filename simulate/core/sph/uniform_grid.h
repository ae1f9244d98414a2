#pragma once
// Uniform grid neighbour search (Green 2009): cell size = support radius h,
// particles sorted by linear cell index, each cell's range [begin, end) in
// the sorted order. A query visits the 27 cells around a position.
#include <algorithm>
#include <cstdint>

#include "backend/host_device.h"
#include "math/vec3.h"

namespace dp {

struct UniformGrid {
  Vec3 origin;
  float cell_size = 1;
  int nx = 1, ny = 1, nz = 1;

  DP_HD std::uint32_t cell_count() const { return static_cast<std::uint32_t>(nx) * ny * nz; }

  DP_HD int clamp_axis(float v, int n) const {
    int c = static_cast<int>(floorf(v));
    return c < 0 ? 0 : (c >= n ? n - 1 : c);
  }
  DP_HD void cell_of(Vec3 p, int& i, int& j, int& k) const {
    i = clamp_axis((p.x - origin.x) / cell_size, nx);
    j = clamp_axis((p.y - origin.y) / cell_size, ny);
    k = clamp_axis((p.z - origin.z) / cell_size, nz);
  }
  DP_HD std::uint32_t linear(int i, int j, int k) const {
    return (static_cast<std::uint32_t>(k) * ny + j) * nx + i;
  }
  DP_HD std::uint32_t key_of(Vec3 p) const {
    int i, j, k;
    cell_of(p, i, j, k);
    return linear(i, j, k);
  }
};

// The sorted view of one particle set in a grid. Every cell, empty or not,
// has its range [cell_begin[c], cell_end[c]) in the sorted order, so the
// three cells of a row along x (consecutive linear indices) form one
// contiguous range.
struct GridView {
  UniformGrid grid;
  const std::uint32_t* cell_begin;  // per cell, first sorted index
  const std::uint32_t* cell_end;    // per cell, one past the last (ParticleGrid: cell_begin + 1)
  const Vec3* position;             // sorted positions

  // Calls f(j) for every particle j within the 27 cells around p, as nine
  // contiguous runs (one per row of three cells along x).
  template <class F>
  DP_HD void for_each_near(Vec3 p, const F& f) const {
    for_each_run_near(p, [&](std::uint32_t first, std::uint32_t end) {
      for (std::uint32_t n = first; n < end; ++n) f(n);
    });
  }

  // A box of cells, inclusive on every axis; each of its rows along x is one
  // contiguous run of particles, [row_first, row_end).
  struct CellBox {
    int i0, i1, j0, j1, k0, k1;
  };
  DP_HD std::uint32_t row_first(const CellBox& b, int j, int k) const { return cell_begin[grid.linear(b.i0, j, k)]; }
  DP_HD std::uint32_t row_end(const CellBox& b, int j, int k) const { return cell_end[grid.linear(b.i1, j, k)]; }

  // The 27 cells around p, less those outside the grid.
  DP_HD CellBox cells_near(Vec3 p) const {
    int ci, cj, ck;
    grid.cell_of(p, ci, cj, ck);
    return CellBox{ci > 0 ? ci - 1 : 0, ci + 1 < grid.nx ? ci + 1 : grid.nx - 1,
                   cj > 0 ? cj - 1 : 0, cj + 1 < grid.ny ? cj + 1 : grid.ny - 1,
                   ck > 0 ? ck - 1 : 0, ck + 1 < grid.nz ? ck + 1 : grid.nz - 1};
  }

  // The cells that overlap the box of half-width `radius` around p: every
  // particle closer to p than radius lies in them; for a radius below the
  // cell size, one to eight cells in place of 27. The box is widened by a
  // part in 10^4 so that rounding in the cell lookups cannot drop a cell
  // that such a particle lies in. A negative radius gives an empty box.
  DP_HD CellBox cells_within(Vec3 p, float radius) const {
    const float r = radius * 1.0001f;
    CellBox b;
    grid.cell_of(p - Vec3{r, r, r}, b.i0, b.j0, b.k0);
    grid.cell_of(p + Vec3{r, r, r}, b.i1, b.j1, b.k1);
    return b;
  }

  // f(first, end) for each row of the box, in the sorted order.
  template <class F>
  DP_HD void for_each_run_in(const CellBox& b, const F& f) const {
    for (int k = b.k0; k <= b.k1; ++k)
      for (int j = b.j0; j <= b.j1; ++j) f(row_first(b, j, k), row_end(b, j, k));
  }

  // The same particles as for_each_near, as runs: f(first, end) for each of
  // the nine rows.
  template <class F>
  DP_HD void for_each_run_near(Vec3 p, const F& f) const {
    for_each_run_in(cells_near(p), f);
  }

  // The runs of cells_within(p, radius), in the walk's order.
  template <class F>
  DP_HD void for_each_run_within(Vec3 p, float radius, const F& f) const {
    for_each_run_in(cells_within(p, radius), f);
  }
};

// Kernels that build a GridView from particles; see ParticleGrid in
// particle_grid.h for the sequence.
struct ComputeCellKeys {
  UniformGrid grid;
  const Vec3* position;
  std::uint32_t* key;
  std::uint32_t* index;
  DP_HD void operator()(std::size_t i) const {
    key[i] = grid.key_of(position[i]);
    index[i] = static_cast<std::uint32_t>(i);
  }
};

// cell_begin[c] = the first sorted index whose key is c or more, n where
// there is none: cell c's range begins there, and cell c - 1's ends there.
// Element i of a pass is cell first_cell + i, up to cell_count() (one past
// the last cell), each entry by its own search, so no count has to be
// cleared and scanned over the whole grid first (a domain of millions of
// mostly empty cells made that the largest part of a step's neighbour
// search).
struct CellBegins {
  const std::uint32_t* sorted_key;
  std::uint32_t n;
  std::uint32_t* cell_begin;
  std::uint32_t first_cell = 0;

  DP_HD std::uint32_t first_at_or_after(std::uint32_t c) const {
    std::uint32_t low = 0, high = n;
    while (low < high) {
      const std::uint32_t mid = low + (high - low) / 2;
      if (sorted_key[mid] < c) low = mid + 1;
      else high = mid;
    }
    return low;
  }
  DP_HD void operator()(std::size_t i) const {
    const std::uint32_t c = first_cell + static_cast<std::uint32_t>(i);
    cell_begin[c] = first_at_or_after(c);
  }
  // Elements begin .. end - 1 at once (CpuExec): one search, then a walk
  // along the runs of equal keys. Every cell from the one after the last
  // run's key up to the next run's key begins where that run does, so each
  // gap of empty cells is one fill (a stream of stores, where a step per
  // cell took 3.6 ms a step on the air benchmark's 4M mostly empty cells).
  DP_HOST_INLINE void whole_range(std::size_t begin_element, std::size_t end_element) const {
    const std::size_t begin = first_cell + begin_element, end = first_cell + end_element;
    std::uint32_t first = first_at_or_after(static_cast<std::uint32_t>(begin));
    for (std::size_t c = begin; c < end;) {
      const std::size_t last = first < n && sorted_key[first] < end ? sorted_key[first] : end - 1;
      std::fill(cell_begin + c, cell_begin + last + 1, first);
      c = last + 1;
      if (first < n) {
        const std::uint32_t run = sorted_key[first];
        while (first < n && sorted_key[first] == run) ++first;
      }
    }
  }
};

}  // namespace dp
