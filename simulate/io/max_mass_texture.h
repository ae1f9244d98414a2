#pragma once
// The maximum-mass texture m_t^max (paper Sec. 4.3): how much water each texel
// may hold, kg. Either a constant per area or an image over the atlas (the
// paper's impregnated SCA logo): its value, taken as data (no colour
// transform; the luminance of RGB) and resampled to the texture's
// resolution, times a scale in kg/m^2. OpenEXR files are read with OpenEXR,
// every other format (PNG, JPEG, TGA, BMP, PNM, 8 or 16 bits) with
// stb_image: the simulator links no image library's plug-in closure.
#include <filesystem>

#include "surface/surface_texture_setup.h"

namespace dp::io {

void set_constant_max_mass(TexelGeometry& texels, double kg_per_m2);

// Throws std::runtime_error naming the image when it cannot be read.
void set_max_mass_from_image(TexelGeometry& texels, const std::filesystem::path& image, double kg_per_m2_at_one);

}  // namespace dp::io
