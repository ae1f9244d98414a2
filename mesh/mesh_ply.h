#pragma once
// The liquid mesh file (docs/file-formats.md): binary PLY with float x, y, z,
// nx, ny, nz per vertex and triangles, counter-clockwise seen from outside.
#include <filesystem>
#include <string>

#include "ply.h"
#include "surface_mesh.h"

namespace dp::mesh {

io::PlyData mesh_to_ply(const SurfaceMesh& mesh, const std::string& comment);

// Written atomically.
void write_mesh_ply(const std::filesystem::path& file, const SurfaceMesh& mesh, const std::string& comment);

}  // namespace dp::mesh
