#pragma once
// Rigid-surface files of the frames folder (docs/file-formats.md):
// rigid_NAME.ply, the rigid's mesh with its UV atlas, once per run, and
// surface_NAME.%04d.exr, its dynamic textures per frame.
#include <filesystem>
#include <string>
#include <vector>

#include "simulation.h"
#include "surface_atlas.h"

namespace dp::io {

// Binary little-endian PLY: float x y z nx ny nz s t, triangles.
void write_rigid_atlas_mesh(const std::filesystem::path& file, const AtlasMesh& atlas, const std::string& comment);

// Float EXR, channels mass (kg), max_mass (kg), temperature (K), wetting;
// row 0 at the top; 0 outside every chart. Written atomically.
void write_surface_frame(const std::filesystem::path& file, const SurfaceSnapshot& surface);

// The channel names, in file order.
inline const std::vector<std::string>& surface_channel_names() {
  static const std::vector<std::string> names{"mass", "max_mass", "temperature", "wetting"};
  return names;
}

}  // namespace dp::io
