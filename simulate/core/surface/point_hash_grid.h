#pragma once
// A sparse hash grid over points for the host-side set-up of the surface
// textures (seeding, texel assignment): cells of a fixed size, keyed by their
// integer coordinates. The device neighbour search (sph/uniform_grid.h)
// needs a dense grid over the simulation domain; this one needs no bounds
// and is used once, before the simulation starts.
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "math/vec3.h"

namespace dp {

class PointHashGrid {
 public:
  explicit PointHashGrid(float cell_size) : cell_(cell_size) {}

  void insert(Vec3 p, std::uint32_t id) { cells_[key(cell_of(p.x), cell_of(p.y), cell_of(p.z))].push_back(id); }

  // Calls f(id) for every id in the cells that can hold points within
  // `radius` of p (the cube of cells around p's cell).
  template <class F>
  void for_each_near(Vec3 p, float radius, const F& f) const {
    const int reach = static_cast<int>(std::ceil(radius / cell_));
    const std::int64_t ci = cell_of(p.x), cj = cell_of(p.y), ck = cell_of(p.z);
    for (std::int64_t k = ck - reach; k <= ck + reach; ++k)
      for (std::int64_t j = cj - reach; j <= cj + reach; ++j)
        for (std::int64_t i = ci - reach; i <= ci + reach; ++i) {
          auto it = cells_.find(key(i, j, k));
          if (it == cells_.end()) continue;
          for (std::uint32_t id : it->second) f(id);
        }
  }

 private:
  std::int64_t cell_of(float v) const { return static_cast<std::int64_t>(std::floor(v / cell_)); }
  static std::uint64_t key(std::int64_t i, std::int64_t j, std::int64_t k) {
    // 21 bits per axis around the origin: +-1e6 cells.
    const std::int64_t bias = 1 << 20;
    return (static_cast<std::uint64_t>(i + bias) & 0x1fffff) | ((static_cast<std::uint64_t>(j + bias) & 0x1fffff) << 21) |
           ((static_cast<std::uint64_t>(k + bias) & 0x1fffff) << 42);
  }

  float cell_;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
};

}  // namespace dp
