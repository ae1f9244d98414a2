#pragma once
// A rigid's mesh with a UV atlas for its surface textures (paper Sec. 4.3):
// every vertex has one (s, t) in [0,1]^2 and vertices are split along chart
// seams. The UVs come from the asset when they form a valid atlas (inside
// [0,1]^2, no two triangles over the same texel, no collapsed triangle);
// otherwise the mesh is cut into charts and each is flattened with CGAL's
// Surface_mesh_parameterization (chart_parameterization.h).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "triangle_mesh.h"

namespace dp::io {

struct AtlasMesh {
  std::vector<std::array<float, 3>> positions;  // world space (m)
  std::vector<std::array<float, 3>> normals;
  std::vector<std::array<float, 2>> uvs;        // (s, t) in [0,1]^2; t = 1 is the top row of the textures
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::string uv_source;                        // "asset" or "generated (reason)"
};

// Throws std::runtime_error naming `mesh_name` when no atlas can be made.
AtlasMesh make_surface_atlas(const TriangleMesh& mesh, int width, int height, const std::string& mesh_name);

}  // namespace dp::io
