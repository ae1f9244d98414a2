#pragma once
// Per-step neighbour lists: for each particle, the indices of the particles
// of a set within the support radius, found once through the grid and then
// read by every PCISPH iteration. A list holds about 30-40 neighbours where
// the 27 grid cells hold about 200 candidates, so the iterations touch
// several times less memory. The GPU builds them by count, exclusive scan
// and fill, each particle writing only its own slice; the CPU in one walk,
// chunk by chunk (FillListChunks). Both are deterministic and give the same
// lists bit for bit.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "backend/host_device.h"
#include "sph/kernel_cubic_spline.h"
#include "sph/uniform_grid.h"

namespace dp {

struct NeighborList {
  const std::uint32_t* offset;  // n + 1 entries
  const std::uint32_t* index;

  template <class F>
  DP_HD void for_each(std::size_t i, const F& f) const {
    for (std::uint32_t k = offset[i]; k < offset[i + 1]; ++k) f(index[k]);
  }
};

// The particles of `set` within radius2 of x, in the order of the grid's
// walk (for_each_near), written to near[0 .. ) for the CPU's whole_range
// paths. The distance tests of a run of candidates are taken in one loop,
// which vectorises; each candidate is then written at the list's end and
// kept by advancing the end by its test's 0 or 1, with no branch: about one
// candidate in six of the 27 cells is a neighbour, at random, and a branch
// on the test was mispredicted on most particles' lists. Returns how many
// are near; only the first `capacity` are written, so `near` holds
// capacity + kNearBlock entries and a caller whose count exceeds capacity
// takes its one-loop path.
inline constexpr std::uint32_t kNearBlock = 64;

DP_HOST_INLINE std::uint32_t gather_near(const GridView& set, Vec3 x, float radius2, std::uint32_t* near,
                                         std::uint32_t capacity) {
  std::uint32_t found = 0, kept = 0;
  std::uint32_t test[kNearBlock];
  // Loops over the rows, not for_each_run_near's callback: a lambda would
  // not inline into the launcher's AVX2 copy of a whole_range.
  const GridView::CellBox box = set.cells_near(x);
  for (int k = box.k0; k <= box.k1; ++k)
    for (int j = box.j0; j <= box.j1; ++j) {
      const std::uint32_t run_end = set.row_end(box, j, k);
      for (std::uint32_t block = set.row_first(box, j, k); block < run_end; block += kNearBlock) {
        const std::uint32_t size = run_end - block < kNearBlock ? run_end - block : kNearBlock;
        const Vec3* position = set.position + block;
        for (std::uint32_t m = 0; m < size; ++m) test[m] = length_squared(x - position[m]) < radius2 ? 1u : 0u;
        kept = kept < capacity ? kept : capacity;  // bounds this block's stores below capacity + kNearBlock
        for (std::uint32_t m = 0; m < size; ++m) {
          near[kept] = block + m;
          kept += test[m];
          found += test[m];
        }
      }
    }
  return found;
}

// Neighbours of particle i of `query` (positions `query_position`) among
// `set`, within radius^2, i itself included when both are the same set.
struct CountNeighbors {
  const Vec3* query_position;
  GridView set;
  float radius2;
  std::uint32_t* count;
  DP_HD void operator()(std::size_t i) const {
    const Vec3 xi = query_position[i];
    std::uint32_t c = 0;
    set.for_each_near(xi, [&](std::uint32_t j) { c += length_squared(xi - set.position[j]) < radius2 ? 1u : 0u; });
    count[i] = c;
  }
};

// Fills each particle's slice, as CountNeighbors sized it (the GPU's lists;
// the CPU's are FillListChunks'). Where
// gradient_factor is given, also each pair's
// CubicSplineKernel::gradient_factor (the kernel's support radius is the
// list's): PCISPH evaluates the pressure force at the positions of the
// step's start in every iteration, so the square root and divisions per
// pair are done here once per step, and the pressure force, heat
// conduction, normals and areas read them (ListedPairs) with the same bits.
struct FillNeighbors {
  const Vec3* query_position;
  GridView set;
  float radius2;
  const std::uint32_t* offset;
  std::uint32_t* index;
  CubicSplineKernel kernel{};
  float* gradient_factor = nullptr;
  DP_HD void operator()(std::size_t i) const {
    const Vec3 xi = query_position[i];
    std::uint32_t k = offset[i];
    set.for_each_near(xi, [&](std::uint32_t j) {
      const Vec3 xij = xi - set.position[j];
      if (!(length_squared(xij) < radius2)) return;  // CountNeighbors' test exactly, NaN included
      if (gradient_factor) gradient_factor[k] = kernel.gradient_factor(xij);
      index[k++] = j;
    });
  }
};

// The CPU's lists in one walk of the grid, where the GPU's take two (count,
// scan, fill). The particles are cut into chunks of kChunk, and each chunk
// appends its particles' lists to buffers of its own; once the counts are
// scanned, CopyListChunks moves each chunk's buffers into place. Chunks
// depend on the particle count alone, so the lists do not depend on the
// thread count, and the pairs, their order and their gradient factors are
// FillNeighbors' bit for bit: the same test (gather_near, without a branch
// per candidate), factors from the same distances. A list longer than
// kMaxListed (never in a liquid at rest density) walks the grid again.
struct ListChunks {
  static constexpr std::size_t kChunk = 2048;
  std::vector<std::vector<std::uint32_t>> index;
  std::vector<std::vector<float>> gradient_factor;

  static std::size_t chunks_of(std::size_t n) { return (n + kChunk - 1) / kChunk; }
  void resize(std::size_t n) {
    index.resize(chunks_of(n));
    gradient_factor.resize(chunks_of(n));
  }
  // The chunks c that start in [begin, end), first_starting_at(begin) <= c
  // and c * kChunk < end: a whole_range share of any parallel_for over the
  // particles takes each chunk once. (A loop, not a callback: a lambda
  // would not inline into the launcher's AVX2 copy.)
  static std::size_t first_starting_at(std::size_t begin) { return (begin + kChunk - 1) / kChunk; }
};

struct FillListChunks {
  static constexpr std::uint32_t kMaxListed = 192;
  const Vec3* query_position;
  GridView set;
  float radius2;
  CubicSplineKernel kernel;
  bool with_gradients;
  std::size_t n;
  std::uint32_t* count;
  ListChunks* chunks;

  // Inlined, as every whole_range, into the launcher's AVX2 copy.
  DP_HOST_INLINE void whole_range(std::size_t begin, std::size_t end) const {
    for (std::size_t c = ListChunks::first_starting_at(begin); c * ListChunks::kChunk < end; ++c) fill(c);
  }

 private:
  DP_HOST_INLINE void fill(std::size_t c) const {
    std::vector<std::uint32_t>& index = chunks->index[c];
    std::vector<float>& factor = chunks->gradient_factor[c];
    index.clear();
    factor.clear();
    std::uint32_t local[kMaxListed + kNearBlock];
    float distance[kMaxListed];
    const std::size_t last = (c + 1) * ListChunks::kChunk < n ? (c + 1) * ListChunks::kChunk : n;
    for (std::size_t i = c * ListChunks::kChunk; i < last; ++i) {
      const Vec3 xi = query_position[i];
      std::uint32_t found = gather_near(set, xi, radius2, local, kMaxListed);
      if (found > kMaxListed) {
        const std::size_t first = index.size();
        set.for_each_near(xi, [&](std::uint32_t j) {
          if (length_squared(xi - set.position[j]) < radius2) index.push_back(j);
        });
        if (with_gradients)
          for (std::size_t k = first; k < index.size(); ++k) factor.push_back(kernel.gradient_factor(xi - set.position[index[k]]));
      } else {
        index.insert(index.end(), local, local + found);
        if (with_gradients) {
          for (std::uint32_t k = 0; k < found; ++k) distance[k] = length(xi - set.position[local[k]]);
          const std::size_t first = factor.size();
          factor.resize(first + found);
          for (std::uint32_t k = 0; k < found; ++k) factor[first + k] = kernel.gradient_factor_at(distance[k]);
        }
      }
      count[i] = found;
    }
  }
};

struct CopyListChunks {
  const ListChunks* chunks;
  const std::uint32_t* offset;
  std::uint32_t* index;
  float* gradient_factor;  // null: no factors

  DP_HOST_INLINE void whole_range(std::size_t begin, std::size_t end) const {
    for (std::size_t c = ListChunks::first_starting_at(begin); c * ListChunks::kChunk < end; ++c) {
      const std::uint32_t first = offset[c * ListChunks::kChunk];
      std::copy(chunks->index[c].begin(), chunks->index[c].end(), index + first);
      if (gradient_factor)
        std::copy(chunks->gradient_factor[c].begin(), chunks->gradient_factor[c].end(), gradient_factor + first);
    }
  }
};

// The scan's extra last entry, so that offset[n] is the total.
struct ClearLastCount {
  std::uint32_t* count;
  std::size_t n;
  DP_HD void operator()(std::size_t) const { count[n] = 0; }
};

// A list's pairs with their gradient factors, for a kernel that can also
// walk the grid: without a list (offset null) it does.
struct ListedPairs {
  NeighborList list{nullptr, nullptr};
  const float* gradient_factor = nullptr;
  DP_HD bool present() const { return list.offset != nullptr; }
};

// Calls f(j, x_i - x_j, entry) for every particle j of `set` closer to x_i
// than the support radius h, i itself included when `set` is its own: from
// `pairs` where the step listed them (entry: the pair's place in the list),
// else by a walk over the grid's cells (entry: kNotListed). The list was
// filled by that walk with the same test, so both give the same pairs in
// the same order, and the same sums bit for bit.
inline constexpr std::uint32_t kNotListed = 0xffffffffu;

// Always inlined, as for_each_pair_gradient: out of line, with their
// callers' lambdas, they ran as baseline code (docs/architecture.md).
template <class F>
DP_HD_INLINE void for_each_pair(const GridView& set, const ListedPairs& pairs, std::size_t i, Vec3 xi, float h, const F& f) {
  if (pairs.present()) {
    for (std::uint32_t k = pairs.list.offset[i]; k < pairs.list.offset[i + 1]; ++k) {
      const std::uint32_t j = pairs.list.index[k];
      f(j, xi - set.position[j], k);
    }
    return;
  }
  const float h2 = h * h;
  set.for_each_near(xi, [&](std::uint32_t j) {
    const Vec3 xij = xi - set.position[j];
    if (length_squared(xij) < h2) f(j, xij, kNotListed);
  });
}

// for_each_pair with f(j, x_i - x_j, gradW_ij): the listed factor where
// there is one.
template <class F>
DP_HD_INLINE void for_each_pair_gradient(const GridView& set, const ListedPairs& pairs, std::size_t i, Vec3 xi,
                                         const CubicSplineKernel& kernel, const F& f) {
  for_each_pair(set, pairs, i, xi, kernel.h, [&](std::uint32_t j, Vec3 xij, std::uint32_t entry) {
    f(j, xij, entry != kNotListed ? pairs.gradient_factor[entry] * xij : kernel.gradW(xij));
  });
}

// Storage and building of one list on a backend.
template <class Exec>
struct NeighborListBuffers {
  typename Exec::template Buffer<std::uint32_t> count, offset, index;
  typename Exec::template Buffer<float> gradient_factor;  // build_with_gradients only
  ListChunks chunks;                                      // the CPU's one-walk fill (FillListChunks)

  NeighborList build(const Exec& exec, const typename Exec::template Buffer<Vec3>& query, const GridView& set,
                     float radius) {
    return fill(exec, query, set, radius * radius, CubicSplineKernel{}, false);
  }

  // The list within the kernel's support, with each pair's gradient factor.
  ListedPairs build_with_gradients(const Exec& exec, const typename Exec::template Buffer<Vec3>& query, const GridView& set,
                                   const CubicSplineKernel& kernel) {
    const NeighborList list = fill(exec, query, set, kernel.h * kernel.h, kernel, true);
    return ListedPairs{list, Exec::ptr(gradient_factor)};
  }

 private:
  NeighborList fill(const Exec& exec, const typename Exec::template Buffer<Vec3>& query, const GridView& set, float r2,
                    const CubicSplineKernel& kernel, bool with_gradients) {
    const std::size_t n = query.size();
    count.resize(n + 1);
    if constexpr (Exec::kBuffersInHostMemory) {
      chunks.resize(n);
      exec.parallel_for(n, FillListChunks{Exec::ptr(query), set, r2, kernel, with_gradients, n, Exec::ptr(count), &chunks});
    } else {
      exec.parallel_for(n, CountNeighbors{Exec::ptr(query), set, r2, Exec::ptr(count)});
    }
    exec.parallel_for(1, ClearLastCount{Exec::ptr(count), n});
    exec.exclusive_scan(count, offset);
    const std::uint32_t total = Exec::download_one(offset, n);
    index.resize(total);
    if (with_gradients) gradient_factor.resize(total);
    float* factor = with_gradients ? Exec::ptr(gradient_factor) : nullptr;
    if constexpr (Exec::kBuffersInHostMemory) {
      exec.parallel_for(n, CopyListChunks{&chunks, Exec::ptr(offset), Exec::ptr(index), factor});
    } else {
      exec.parallel_for(n, FillNeighbors{Exec::ptr(query), set, r2, Exec::ptr(offset), Exec::ptr(index), kernel, factor});
    }
    return NeighborList{Exec::ptr(offset), Exec::ptr(index)};
  }
};

}  // namespace dp
