#include "marching_cubes.h"

#include <stdexcept>
#include <unordered_map>

#include "cube_topology.h"
#include "cube_triangulation.h"

namespace dp::mesh {

namespace {

using NodeIndex = std::array<int, 3>;

double field_at(const ScalarGrid& grid, NodeIndex n) { return grid.at(n[0], n[1], n[2]); }

// Central differences inside the grid, one-sided on its boundary.
Vec3d field_gradient(const ScalarGrid& grid, NodeIndex n) {
  Vec3d g;
  for (int axis = 0; axis < 3; ++axis) {
    NodeIndex lo = n, hi = n;
    if (n[axis] > 0) --lo[axis];
    if (n[axis] + 1 < grid.box.nodes[axis]) ++hi[axis];
    const int steps = hi[axis] - lo[axis];
    g[axis] = steps > 0 ? (field_at(grid, hi) - field_at(grid, lo)) / (steps * grid.box.voxel_size) : 0.0;
  }
  return g;
}

// Where the field, linear along the edge, is zero: the fraction of the way
// from the lower node to the upper one.
double zero_crossing_fraction(double lower, double upper) { return lower / (lower - upper); }

class EdgeVertices {
 public:
  EdgeVertices(const ScalarGrid& grid, SurfaceMesh& mesh) : grid_(grid), mesh_(mesh) {}

  // The vertex on the grid edge from node `lower` along `axis`, made on first use.
  std::uint32_t vertex_on(NodeIndex lower, int axis) {
    const std::int64_t key = 3 * grid_.box.node_index(lower[0], lower[1], lower[2]) + axis;
    auto [it, inserted] = vertex_of_edge_.try_emplace(key, static_cast<std::uint32_t>(mesh_.position.size()));
    if (inserted) add_vertex(lower, axis);
    return it->second;
  }

 private:
  void add_vertex(NodeIndex lower, int axis) {
    NodeIndex upper = lower;
    ++upper[axis];
    const double t = zero_crossing_fraction(field_at(grid_, lower), field_at(grid_, upper));
    Vec3d p = grid_.box.node_position(lower[0], lower[1], lower[2]);
    p[axis] += t * grid_.box.voxel_size;
    mesh_.position.push_back(p);
    mesh_.normal.push_back(normalized((1 - t) * field_gradient(grid_, lower) + t * field_gradient(grid_, upper)));
  }

  const ScalarGrid& grid_;
  SurfaceMesh& mesh_;
  std::unordered_map<std::int64_t, std::uint32_t> vertex_of_edge_;
};

int inside_corners(const ScalarGrid& grid, NodeIndex cube) {
  int inside = 0;
  for (int c = 0; c < kCubeCorners; ++c)
    if (grid.at(cube[0] + corner_coordinate(c, 0), cube[1] + corner_coordinate(c, 1), cube[2] + corner_coordinate(c, 2)) < 0)
      inside |= 1 << c;
  return inside;
}

NodeIndex edge_lower_node(NodeIndex cube, int edge) {
  const int c = edge_lower_corner(edge);
  return {cube[0] + corner_coordinate(c, 0), cube[1] + corner_coordinate(c, 1), cube[2] + corner_coordinate(c, 2)};
}

}  // namespace

SurfaceMesh marching_cubes(const ScalarGrid& grid) {
  if (grid.values.size() != static_cast<std::size_t>(grid.box.node_count()))
    throw std::invalid_argument("marching_cubes: grid values do not match its box");
  const auto& table = cube_triangulations();
  SurfaceMesh mesh;
  EdgeVertices vertices(grid, mesh);
  const auto& n = grid.box.nodes;
  // Serial in a fixed order: vertex and triangle numbering are then the
  // same on every run.
  for (int k = 0; k + 1 < n[2]; ++k)
    for (int j = 0; j + 1 < n[1]; ++j)
      for (int i = 0; i + 1 < n[0]; ++i) {
        const NodeIndex cube{i, j, k};
        const int inside = inside_corners(grid, cube);
        for (const auto& triangle : table[inside].triangles) {
          std::array<std::uint32_t, 3> t;
          for (int v = 0; v < 3; ++v) t[v] = vertices.vertex_on(edge_lower_node(cube, triangle[v]), edge_axis(triangle[v]));
          mesh.triangles.push_back(t);
        }
      }
  return mesh;
}

}  // namespace dp::mesh
