#pragma once
// The liquid surface of one frame, as dewpoint-mesh writes it: a binary PLY
// with vertex properties x, y, z, nx, ny, nz and triangle faces
// (docs/file-formats.md). A frame may have no triangles at all.
#include <filesystem>

#include "triangle_mesh.h"

namespace dp::render {

// Throws std::runtime_error naming the file and what is missing.
dp::io::TriangleMesh load_liquid_mesh(const std::filesystem::path& file);

}  // namespace dp::render
