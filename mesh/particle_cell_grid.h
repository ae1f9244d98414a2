#pragma once
// Uniform cell grid over the particles' bounding box for fixed-radius
// neighbour queries: cells as wide as the query radius, so the neighbours of
// any point lie in the 3x3x3 cells around it. Particles are stored sorted by
// cell (a counting sort), so a query visits them in one fixed order: sums
// over neighbours come out bit-identical however queries are scheduled.
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "vec3d.h"

namespace dp::mesh {

class ParticleCellGrid {
 public:
  // Keeps a reference to `position`, which must outlive the grid.
  ParticleCellGrid(const std::vector<Vec3d>& position, double cell_size);

  // Calls visit(particle index, offset from x to the particle, squared
  // distance) for every particle closer to x than the cell size.
  template <class Visit>
  void for_each_neighbour(Vec3d x, const Visit& visit) const;

  // Calls visit(particle index) for every particle in the cells that
  // overlap the box [lo, hi], cell by cell in memory order: a superset of
  // the particles in the box, in an order fixed by the particles alone.
  template <class Visit>
  void for_each_in_box(Vec3d lo, Vec3d hi, const Visit& visit) const;

 private:
  std::array<std::int64_t, 3> cell_of(Vec3d x) const;

  const std::vector<Vec3d>& position_;
  double cell_size_;
  Vec3d origin_;
  std::array<std::int64_t, 3> cells_{0, 0, 0};
  std::vector<std::uint32_t> cell_start_;  // per cell, then one past the end
  std::vector<std::uint32_t> sorted_;      // particle indices grouped by cell
};

template <class Visit>
void ParticleCellGrid::for_each_neighbour(Vec3d x, const Visit& visit) const {
  if (sorted_.empty()) return;
  const auto c = cell_of(x);
  const double reach_squared = cell_size_ * cell_size_;
  for (std::int64_t k = std::max<std::int64_t>(c[2] - 1, 0); k <= std::min(c[2] + 1, cells_[2] - 1); ++k)
    for (std::int64_t j = std::max<std::int64_t>(c[1] - 1, 0); j <= std::min(c[1] + 1, cells_[1] - 1); ++j) {
      const std::int64_t i0 = std::max<std::int64_t>(c[0] - 1, 0), i1 = std::min(c[0] + 1, cells_[0] - 1);
      if (i0 > i1) continue;
      // Cells along x are adjacent in memory: one run covers the three.
      const std::int64_t row = (k * cells_[1] + j) * cells_[0];
      for (std::uint32_t s = cell_start_[row + i0]; s < cell_start_[row + i1 + 1]; ++s) {
        const std::uint32_t p = sorted_[s];
        const Vec3d d = position_[p] - x;
        const double r2 = length_squared(d);
        if (r2 < reach_squared) visit(p, d, r2);
      }
    }
}

template <class Visit>
void ParticleCellGrid::for_each_in_box(Vec3d lo, Vec3d hi, const Visit& visit) const {
  if (sorted_.empty()) return;
  const auto a = cell_of(lo), b = cell_of(hi);
  for (std::int64_t k = std::max<std::int64_t>(a[2], 0); k <= std::min(b[2], cells_[2] - 1); ++k)
    for (std::int64_t j = std::max<std::int64_t>(a[1], 0); j <= std::min(b[1], cells_[1] - 1); ++j) {
      const std::int64_t i0 = std::max<std::int64_t>(a[0], 0), i1 = std::min(b[0], cells_[0] - 1);
      if (i0 > i1) continue;
      const std::int64_t row = (k * cells_[1] + j) * cells_[0];
      for (std::uint32_t s = cell_start_[row + i0]; s < cell_start_[row + i1 + 1]; ++s) visit(sorted_[s]);
    }
}

}  // namespace dp::mesh
