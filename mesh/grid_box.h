#pragma once
// The lattice of sample points (nodes) on which a scalar field is stored and
// marching cubes runs: nodes at origin + voxel_size * (i, j, k).
#include <array>
#include <cstdint>

#include "vec3d.h"

namespace dp::mesh {

struct GridBox {
  Vec3d origin;
  double voxel_size = 1;
  std::array<int, 3> nodes{0, 0, 0};  // node count per axis; cubes are one fewer

  std::int64_t node_count() const { return std::int64_t{nodes[0]} * nodes[1] * nodes[2]; }
  std::int64_t node_index(int i, int j, int k) const {
    return (std::int64_t{k} * nodes[1] + j) * nodes[0] + i;
  }
  Vec3d node_position(int i, int j, int k) const {
    return origin + voxel_size * Vec3d{double(i), double(j), double(k)};
  }
};

// The box covering [lo, hi] grown by `margin` on every side. The origin is a
// whole multiple of the voxel size so that the lattice does not shift with
// the particles from frame to frame (shifting lattices make surfaces shimmer).
// Throws std::runtime_error when the box would need more than max_nodes nodes.
GridBox covering_grid(Vec3d lo, Vec3d hi, double voxel_size, double margin,
                      std::int64_t max_nodes = std::int64_t{1} << 29);

}  // namespace dp::mesh
