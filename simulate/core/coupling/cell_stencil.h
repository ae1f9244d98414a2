#pragma once
// Surfel <-> cell neighbourhoods (paper Sec. 4.4): a surfel (texel or liquid
// particle) at x meets the eight cells whose centres surround x, with the
// trilinear weights alpha_sc of x (Sec. 5.1, 6.1). Stencils are stored as
// eight (cell, alpha) pairs per surfel, pair p = 8 s + k; CellPairIndex
// lists for every cell some pair names the pairs that name it, so a cell
// gathers what its surfels give it instead of the surfels scattering into
// it, and cells no surfel reaches cost nothing.
#include <cstdint>
#include <vector>

#include "air/cell_kind.h"
#include "air/mac_grid.h"
#include "backend/counting_sort.h"
#include "backend/host_device.h"
#include "backend/sorted_runs.h"
#include "math/vec3.h"

namespace dp {

inline constexpr int kStencilSize = 8;

// Alpha weights of the eight cell centres around p; outside the grid the
// stencil is clamped to the boundary cells (weights still sum to 1). Pair k
// goes to cell[k * stride], alpha[k * stride].
DP_HD inline void trilinear_stencil(const MacGrid& g, Vec3 p, std::uint32_t* cell, float* alpha, std::size_t stride = 1) {
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
    cell[k * stride] = static_cast<std::uint32_t>(g.cell(i, j, l));
    alpha[k * stride] = (dx ? t[0] : 1 - t[0]) * (dy ? t[1] : 1 - t[1]) * (dz ? t[2] : 1 - t[2]);
  }
}

struct ComputeStencils {
  MacGrid grid;
  const Vec3* position;
  std::uint32_t* pair_cell;
  float* pair_alpha;
  DP_HD void operator()(std::size_t s) const { trilinear_stencil(grid, position[s], pair_cell + kStencilSize * s, pair_alpha + kStencilSize * s); }
};

// Texels keep their pairs corner-major, pair (t, k) at k n + t for n
// texels: the texels whose k-th corner is a given cell are neighbours in a
// row of the atlas, so a cell gathering its pairs reads runs of adjacent
// entries instead of one entry per cache line.
DP_HD inline std::size_t corner_major_pair(std::size_t t, int k, std::size_t n) { return static_cast<std::size_t>(k) * n + t; }

// A texel's stencil is taken one cell in front of it, at x_t + dx n_t: the
// air it touches. At the texel itself, the eight cells around a thin rigid
// (a mirror, a glass wall) are mostly the solid cells holding its particles
// and, on a rigid lying near a cell face, air cells on its other side; one
// cell along the normal the stencil always reaches the air on the texel's
// own side (docs/paper-map.md, departures).
// Pairs corner-major (corner_major_pair) over `count` texels.
struct ComputeStencilsInFront {
  MacGrid grid;
  const Vec3* position;
  const Vec3* normal;  // unit
  std::uint32_t* pair_cell;
  float* pair_alpha;
  std::size_t count;
  DP_HD void operator()(std::size_t s) const {
    trilinear_stencil(grid, position[s] + grid.dx * normal[s], pair_cell + s, pair_alpha + s, count);
  }
};

// The same at the texels themselves (tests of Alg. 2 alone).
struct ComputeTexelStencils {
  MacGrid grid;
  const Vec3* position;
  std::uint32_t* pair_cell;
  float* pair_alpha;
  std::size_t count;
  DP_HD void operator()(std::size_t s) const { trilinear_stencil(grid, position[s], pair_cell + s, pair_alpha + s, count); }
};

// Corner-major stencils of surfels `order[s]` gathered as surfel s's.
struct PermuteCornerMajor {
  const std::uint32_t* order;
  std::size_t count;
  const std::uint32_t* from_cell;
  const float* from_alpha;
  std::uint32_t* cell;
  float* alpha;
  DP_HD void operator()(std::size_t s) const {
    for (int k = 0; k < kStencilSize; ++k) {
      cell[corner_major_pair(s, k, count)] = from_cell[corner_major_pair(order[s], k, count)];
      alpha[corner_major_pair(s, k, count)] = from_alpha[corner_major_pair(order[s], k, count)];
    }
  }
};

// A corner-major surfel's eight cells and alphas, gathered.
DP_HD inline void load_corner_major(const std::uint32_t* pair_cell, const float* pair_alpha, std::size_t t, std::size_t n,
                                    std::uint32_t* cell, float* alpha) {
  for (int k = 0; k < kStencilSize; ++k) {
    cell[k] = pair_cell[corner_major_pair(t, k, n)];
    alpha[k] = pair_alpha[corner_major_pair(t, k, n)];
  }
}

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

// x / wsum for a stencil's weight sum wsum. The weights of a point whose
// eight cells all carry air add up to exactly 1 in float for most points
// (85 % of SCA Logo's texels), and x / 1 is x exactly: a caller that has
// checked wsum == 1 (kUnitSum) skips the division, with the same result.
template <bool kUnitSum, class T>
DP_HD inline T over_weight_sum(T x, float wsum) {
  if constexpr (kUnitSum) return x;
  return x / wsum;
}

struct Iota {
  std::uint32_t* out;
  DP_HD void operator()(std::size_t i) const { out[i] = static_cast<std::uint32_t>(i); }
};

// A cell's pairs as stretches of consecutive pair indices: stretch s holds
// pairs first_pair[s] + [0, begin[s + 1] - begin[s]), and cell run r the
// stretches [run_first[r], run_first[r + 1]).
struct PairStretches {
  const std::uint32_t* run_first;   // active cells + 1
  const std::uint32_t* first_pair;  // per stretch
  const std::uint32_t* begin;       // per stretch, + 1: its first entry in cell order
};

// The pairs of the runs before run r, for parallel_for_by_work.
struct PairsBeforeRun {
  PairStretches pairs;
  std::size_t operator()(std::size_t r) const { return pairs.begin[pairs.run_first[r]]; }
};

// A stretch starts at a cell's first pair and wherever the next pair of the
// same cell is not the one after the last.
struct StretchStarts {
  const std::uint32_t* sorted_cell;
  const std::uint32_t* sorted_pair;
  DP_HD bool operator()(std::size_t q) const {
    return q == 0 || sorted_cell[q] != sorted_cell[q - 1] || sorted_pair[q] != sorted_pair[q - 1] + 1;
  }
};

struct FirstStretchOfRun {
  const std::uint32_t* run_begin;        // active cells + 1
  const std::uint32_t* stretches_before;  // per entry in cell order
  std::size_t cells, stretches;
  std::uint32_t* run_first;
  DP_HD void operator()(std::size_t r) const {
    run_first[r] = r < cells ? stretches_before[run_begin[r]] : static_cast<std::uint32_t>(stretches);
  }
};

// The pairs that name a cell, for the cells some pair names (the active
// cells): run r is cell runs.key[r], whose pairs are
// sorted_pair[runs.begin[r], runs.begin[r + 1]) in surfel order. Cell-side
// kernels run over these runs, not over the whole grid.
template <class Exec>
struct CellPairIndex {
  template <class T>
  using Buffer = typename Exec::template Buffer<T>;
  Buffer<std::uint32_t> sorted_pair;  // pairs in cell order (stable: surfel order within a cell)
  Buffer<std::uint32_t> sorted_cell;
  SortedRuns<Exec> runs;

  // `cells`: the grid's cell count, above every pair's cell. The CPU sorts
  // by counting (backend/counting_sort.h), since the keys are cells: the
  // settled glass's 1.4M liquid pairs take 3.3 ms a step, against 8.5 ms by
  // the general sort. Both give the stable order. The counts it keeps
  // between sorts weigh as much as one grid field per thread.
  void build(const Exec& exec, const Buffer<std::uint32_t>& pair_cell, std::uint32_t cells) {
    const std::size_t n = pair_cell.size();
    if constexpr (Exec::kBuffersInHostMemory) {
      sorted_cell.resize(n);
      sorted_pair.resize(n);
      const int shares = n >= kCountInSharesFrom ? exec.threads() : 1;
      counting_.sort(shares, pair_cell.data(), n, cells, sorted_cell.data(), sorted_pair.data(), runs.key, runs.begin);
      runs.count = runs.key.size();
      return;
    }
    sorted_cell = pair_cell;
    sorted_pair.resize(n);
    exec.parallel_for(n, Iota{Exec::ptr(sorted_pair)});
    exec.sort_by_key(sorted_cell, sorted_pair);
    runs.build(exec, sorted_cell);
  }
  std::size_t active_cells() const { return runs.count; }
  const std::uint32_t* cell() const { return Exec::ptr(runs.key); }
  const std::uint32_t* begin() const { return Exec::ptr(runs.begin); }

  // Static surfels only (texels): corner-major pairs of surfels that share
  // cells come in stretches (texels ordered by cell: about one per corner),
  // so a cell reads its pairs' values in order instead of through one
  // index each.
  void build_stretches(const Exec& exec) {
    stretches_.build_at(exec, sorted_pair, StretchStarts{Exec::ptr(sorted_cell), Exec::ptr(sorted_pair)});
    run_first_stretch_.resize(runs.count + 1);
    exec.parallel_for(runs.count + 1, FirstStretchOfRun{Exec::ptr(runs.begin), stretches_.runs_before(), runs.count, stretches_.count,
                                                        Exec::ptr(run_first_stretch_)});
  }
  PairStretches stretches() const {
    return PairStretches{Exec::ptr(run_first_stretch_), Exec::ptr(stretches_.key), Exec::ptr(stretches_.begin)};
  }

 private:
  static constexpr std::size_t kCountInSharesFrom = 1 << 16;
  CountingSort counting_;
  SortedRuns<Exec> stretches_;
  Buffer<std::uint32_t> run_first_stretch_;
};

// Sets out[c] = value for each listed cell c (clearing what an earlier
// list wrote into a whole-grid array).
template <class T>
struct FillCells {
  const std::uint32_t* cell;
  T value;
  T* out;
  DP_HD void operator()(std::size_t r) const { out[cell[r]] = value; }
};

}  // namespace dp
