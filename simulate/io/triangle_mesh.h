#pragma once
// Rigid meshes as loaded through assimp (OBJ, PLY, glTF, ...), flattened
// into one triangle list in world space.
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace dp::io {

struct TriangleMesh {
  std::vector<std::array<float, 3>> positions;
  std::vector<std::array<float, 3>> normals;  // per vertex, from the file or computed
  std::vector<std::array<float, 2>> uvs;      // empty when the file has none
  std::vector<std::array<std::uint32_t, 3>> triangles;

  double area() const;
};

// Throws std::runtime_error naming the file when it cannot be read (a
// directory, an unknown or damaged format), has no triangles, has zero area
// or is not manifold (an edge shared by more than two triangles, vertices
// compared by position).
TriangleMesh load_triangle_mesh(const std::filesystem::path& file);

// A description of the first edge shared by more than two triangles; empty
// when there is none.
std::string first_non_manifold_edge(const TriangleMesh& mesh);

}  // namespace dp::io
