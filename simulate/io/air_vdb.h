#pragma once
// The air grid per frame as OpenVDB (docs/file-formats.md): FloatGrids
// `vapor_density` (kg/m^3) and `temperature` (K), a Vec3SGrid `velocity`
// (m/s) at cell centres, with the transform placing voxel (i, j, k) at the
// world position of cell (i, j, k)'s centre. Read by Blender and Houdini.
#include <filesystem>
#include <string>

#include "simulation.h"

namespace dp::io {

// Written atomically; throws std::runtime_error naming the file on failure.
void write_air_frame(const std::filesystem::path& file, const AirSnapshot& air, const std::string& comment);

}  // namespace dp::io
