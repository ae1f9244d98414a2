#pragma once
// Per-step neighbour lists: for each particle, the indices of the particles
// of a set within the support radius, found once through the grid and then
// read by every PCISPH iteration. A list holds about 30-40 neighbours where
// the 27 grid cells hold about 200 candidates, so the iterations touch
// several times less memory. Built by count, exclusive scan and fill, each
// particle writing only its own slice: deterministic on both backends.
#include <cstdint>

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

// Fills each particle's slice, as CountNeighbors sized it. Where
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

  // Elements begin .. end - 1 at once (CpuExec). About one candidate in six
  // of the 27 cells is a neighbour, at random, so operator()'s test was a
  // branch mispredicted on most particles' lists and filling took five
  // times as long as counting. Here the tests of a run of candidates are
  // taken in one loop (it vectorises, as CountNeighbors' does), then each
  // candidate is written to a local list and kept by advancing its end by
  // its test's 0 or 1; distances and gradient factors follow in loops of
  // their own over the kept pairs (in one loop with the positions' gathers,
  // g++ leaves the factors' roots and divisions scalar). Same pairs, same order, same bits as
  // operator(); a list longer than kMaxListed (never in a liquid at rest
  // density) takes operator().
  DP_HOST_INLINE void whole_range(std::size_t begin, std::size_t end) const {
    constexpr std::uint32_t kMaxListed = 192, kBlock = 64;
    std::uint32_t local[kMaxListed + kBlock];  // a block's stores land below kept + kBlock
    std::uint32_t near[kBlock];
    float distance[kMaxListed];
    for (std::size_t i = begin; i < end; ++i) {
      const std::uint32_t first = offset[i], count = offset[i + 1] - first;
      if (count > kMaxListed) {
        (*this)(i);
        continue;
      }
      const Vec3 xi = query_position[i];
      std::uint32_t kept = 0;
      set.for_each_run_near(xi, [&](std::uint32_t run_first, std::uint32_t run_end) {
        for (std::uint32_t block = run_first; block < run_end; block += kBlock) {
          const std::uint32_t size = run_end - block < kBlock ? run_end - block : kBlock;
          const Vec3* position = set.position + block;
          for (std::uint32_t m = 0; m < size; ++m) near[m] = length_squared(xi - position[m]) < radius2 ? 1u : 0u;
          kept = kept < count ? kept : count;  // CountNeighbors' count bounds it already; this bounds the stores
          for (std::uint32_t m = 0; m < size; ++m) {
            local[kept] = block + m;
            kept += near[m];
          }
        }
      });
      std::uint32_t* out = index + first;
      for (std::uint32_t k = 0; k < count; ++k) out[k] = local[k];
      if (!gradient_factor) continue;
      for (std::uint32_t k = 0; k < count; ++k) distance[k] = length(xi - set.position[local[k]]);
      float* factor = gradient_factor + first;
      for (std::uint32_t k = 0; k < count; ++k) factor[k] = kernel.gradient_factor_at(distance[k]);
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

template <class F>
DP_HD void for_each_pair(const GridView& set, const ListedPairs& pairs, std::size_t i, Vec3 xi, float h, const F& f) {
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
DP_HD void for_each_pair_gradient(const GridView& set, const ListedPairs& pairs, std::size_t i, Vec3 xi,
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
    exec.parallel_for(n, CountNeighbors{Exec::ptr(query), set, r2, Exec::ptr(count)});
    exec.parallel_for(1, ClearLastCount{Exec::ptr(count), n});
    exec.exclusive_scan(count, offset);
    const std::uint32_t total = Exec::download_one(offset, n);
    index.resize(total);
    if (with_gradients) gradient_factor.resize(total);
    exec.parallel_for(n, FillNeighbors{Exec::ptr(query), set, r2, Exec::ptr(offset), Exec::ptr(index), kernel,
                                       with_gradients ? Exec::ptr(gradient_factor) : nullptr});
    return NeighborList{Exec::ptr(offset), Exec::ptr(index)};
  }
};

}  // namespace dp
