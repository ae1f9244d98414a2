#pragma once
// An indexed triangle mesh with per-vertex normals: the mesher's output.
#include <array>
#include <cstdint>
#include <vector>

#include "vec3d.h"

namespace dp::mesh {

struct SurfaceMesh {
  std::vector<Vec3d> position;
  std::vector<Vec3d> normal;  // unit, outward; one per position
  // Counter-clockwise seen from outside.
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

}  // namespace dp::mesh
