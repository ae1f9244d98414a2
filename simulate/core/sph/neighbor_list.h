#pragma once
// Per-step neighbour lists: for each particle, the indices of the particles
// of a set within the support radius, found once through the grid and then
// read by every PCISPH iteration. A list holds about 30-40 neighbours where
// the 27 grid cells hold about 200 candidates, so the iterations touch
// several times less memory. Built by count, exclusive scan and fill, each
// particle writing only its own slice: deterministic on both backends.
#include <cstdint>

#include "backend/host_device.h"
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

struct FillNeighbors {
  const Vec3* query_position;
  GridView set;
  float radius2;
  const std::uint32_t* offset;
  std::uint32_t* index;
  DP_HD void operator()(std::size_t i) const {
    const Vec3 xi = query_position[i];
    std::uint32_t k = offset[i];
    set.for_each_near(xi, [&](std::uint32_t j) {
      if (length_squared(xi - set.position[j]) < radius2) index[k++] = j;
    });
  }
};

// The scan's extra last entry, so that offset[n] is the total.
struct ClearLastCount {
  std::uint32_t* count;
  std::size_t n;
  DP_HD void operator()(std::size_t) const { count[n] = 0; }
};

// Storage and building of one list on a backend.
template <class Exec>
struct NeighborListBuffers {
  typename Exec::template Buffer<std::uint32_t> count, offset, index;

  NeighborList build(const Exec& exec, const typename Exec::template Buffer<Vec3>& query, const GridView& set,
                     float radius) {
    const std::size_t n = query.size();
    const float r2 = radius * radius;
    count.resize(n + 1);
    exec.parallel_for(n, CountNeighbors{Exec::ptr(query), set, r2, Exec::ptr(count)});
    exec.parallel_for(1, ClearLastCount{Exec::ptr(count), n});
    exec.exclusive_scan(count, offset);
    const std::uint32_t total = Exec::download_one(offset, n);
    index.resize(total);
    exec.parallel_for(n, FillNeighbors{Exec::ptr(query), set, r2, Exec::ptr(offset), Exec::ptr(index)});
    return NeighborList{Exec::ptr(offset), Exec::ptr(index)};
  }
};

}  // namespace dp
