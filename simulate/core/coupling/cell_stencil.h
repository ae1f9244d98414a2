#pragma once
// Surfel <-> cell neighbourhoods (paper Sec. 4.4): a surfel (texel or liquid
// particle) at x meets the eight cells whose centres surround x, with the
// trilinear weights alpha_sc of x (Sec. 5.1, 6.1). Stencils are stored as
// eight (cell, alpha) pairs per surfel, pair p = 8 s + k; CellPairIndex
// lists for every cell the pairs that name it, so a cell gathers what its
// surfels give it instead of the surfels scattering into it.
#include <cstdint>
#include <vector>

#include "air/cell_kind.h"
#include "air/mac_grid.h"
#include "backend/host_device.h"
#include "math/vec3.h"

namespace dp {

inline constexpr int kStencilSize = 8;

// Alpha weights of the eight cell centres around p; outside the grid the
// stencil is clamped to the boundary cells (weights still sum to 1).
DP_HD inline void trilinear_stencil(const MacGrid& g, Vec3 p, std::uint32_t* cell, float* alpha) {
  const Vec3 x = (1.0f / g.dx) * (p - g.origin) - Vec3{0.5f, 0.5f, 0.5f};
  int lo[3];
  float t[3];
  const float c[3] = {x.x, x.y, x.z};
  for (int a = 0; a < 3; ++a) {
    const int n = g.n(a);
    const float f = floorf(c[a]);
    lo[a] = static_cast<int>(f);
    t[a] = c[a] - f;
    if (lo[a] < 0) {
      lo[a] = 0;
      t[a] = 0;
    } else if (lo[a] >= n - 1) {
      lo[a] = n > 1 ? n - 2 : 0;
      t[a] = n > 1 ? 1.0f : 0.0f;
    }
  }
  for (int k = 0; k < kStencilSize; ++k) {
    const int dx = k & 1, dy = (k >> 1) & 1, dz = (k >> 2) & 1;
    const int i = lo[0] + (dx && g.nx > 1 ? 1 : 0), j = lo[1] + (dy && g.ny > 1 ? 1 : 0), l = lo[2] + (dz && g.nz > 1 ? 1 : 0);
    cell[k] = static_cast<std::uint32_t>(g.cell(i, j, l));
    alpha[k] = (dx ? t[0] : 1 - t[0]) * (dy ? t[1] : 1 - t[1]) * (dz ? t[2] : 1 - t[2]);
  }
}

struct ComputeStencils {
  MacGrid grid;
  const Vec3* position;
  std::uint32_t* pair_cell;
  float* pair_alpha;
  DP_HD void operator()(std::size_t s) const { trilinear_stencil(grid, position[s], pair_cell + kStencilSize * s, pair_alpha + kStencilSize * s); }
};

// A texel's stencil is taken one cell in front of it, at x_t + dx n_t: the
// air it touches. At the texel itself, the eight cells around a thin rigid
// (a mirror, a glass wall) are mostly the solid cells holding its particles
// and, on a rigid lying near a cell face, air cells on its other side; one
// cell along the normal the stencil always reaches the air on the texel's
// own side (docs/paper-map.md, departures).
struct ComputeStencilsInFront {
  MacGrid grid;
  const Vec3* position;
  const Vec3* normal;  // unit
  std::uint32_t* pair_cell;
  float* pair_alpha;
  DP_HD void operator()(std::size_t s) const {
    trilinear_stencil(grid, position[s] + grid.dx * normal[s], pair_cell + kStencilSize * s, pair_alpha + kStencilSize * s);
  }
};

// Surfels exchange with the air cells of their stencil, weights
// renormalised over those. A surfel with no air cell among its eight (with
// cells wider than two support radii, Sec. 4.2, a small drop can lie wholly
// inside liquid cells) exchanges with its liquid cells instead, whose vapor
// and heat stay in place while the cell is a wall for the air and move on
// once it is air again. Rigid cells never exchange. Returns the weights' sum
// (0: no cell to exchange with).
DP_HD inline float stencil_weights(const std::uint8_t* kind, const std::uint32_t* cell, const float* alpha, float* w, bool liquid_too) {
  float sum = 0;
  for (int k = 0; k < kStencilSize; ++k) {
    const std::uint8_t c = kind[cell[k]];
    w[k] = (carries_air(c) || (liquid_too && c == kLiquidCell)) ? alpha[k] : 0.0f;
    sum += w[k];
  }
  return sum;
}

DP_HD inline float air_weights(const std::uint8_t* kind, const std::uint32_t* cell, const float* alpha, float* w) {
  const float sum = stencil_weights(kind, cell, alpha, w, false);
  return sum > 0 ? sum : stencil_weights(kind, cell, alpha, w, true);
}

// First pair of each cell in the pairs sorted by cell (binary search), so
// that cell c's pairs are sorted_pair[offset[c], offset[c + 1]).
struct FindCellPairOffsets {
  const std::uint32_t* sorted_cell;
  std::size_t pairs;
  std::uint32_t* offset;
  DP_HD void operator()(std::size_t c) const {
    std::size_t lo = 0, hi = pairs;
    while (lo < hi) {
      const std::size_t mid = (lo + hi) / 2;
      if (sorted_cell[mid] < c) lo = mid + 1;
      else hi = mid;
    }
    offset[c] = static_cast<std::uint32_t>(lo);
  }
};

struct Iota {
  std::uint32_t* out;
  DP_HD void operator()(std::size_t i) const { out[i] = static_cast<std::uint32_t>(i); }
};

template <class Exec>
struct CellPairIndex {
  template <class T>
  using Buffer = typename Exec::template Buffer<T>;
  Buffer<std::uint32_t> offset;       // cell_count + 1
  Buffer<std::uint32_t> sorted_pair;  // pairs in cell order (stable: surfel order within a cell)
  Buffer<std::uint32_t> sorted_cell;

  void build(const Exec& exec, const Buffer<std::uint32_t>& pair_cell, std::size_t cell_count) {
    const std::size_t n = pair_cell.size();
    sorted_cell = pair_cell;
    sorted_pair.resize(n);
    exec.parallel_for(n, Iota{Exec::ptr(sorted_pair)});
    exec.sort_by_key(sorted_cell, sorted_pair);
    offset.resize(cell_count + 1);
    exec.parallel_for(cell_count + 1, FindCellPairOffsets{Exec::ptr(sorted_cell), n, Exec::ptr(offset)});
  }
};

}  // namespace dp
