#pragma once
// Surface-texture and environment-map fixtures, written through
// OpenImageIO as the simulator and a user would write them.
#include <filesystem>
#include <vector>

#include "rgb.h"

namespace dp::render::test {

// A float EXR with channels mass, max_mass, temperature, wetting (width *
// height values each, rows from the top, as the frame-folder contract says).
void write_surface_exr(const std::filesystem::path& file, int width, int height, const std::vector<float>& mass,
                       const std::vector<float>& max_mass, const std::vector<float>& wetting);

// A float RGB EXR.
void write_rgb_exr(const std::filesystem::path& file, int width, int height, const std::vector<Rgb>& pixels);

}  // namespace dp::render::test
