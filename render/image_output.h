#pragma once
// A rendered image on disk: the linear OpenEXR master and an sRGB PNG
// preview. Both land atomically (temporary name, then rename).
#include <filesystem>
#include <string>

#include "image.h"
#include "render_image.h"
#include "render_settings.h"

namespace dp::render {

// RGBA, 32-bit float, linear radiance as rendered (no exposure applied);
// alpha is 1 everywhere, since the sky is part of the picture.
void write_exr(const std::filesystem::path& file, const Image& image, const std::string& software);

// The beauty as above plus the selected auxiliary channels in the same
// file: albedo.R/G/B, normal.X/Y/Z and Z (OpenEXR's depth channel).
void write_exr(const std::filesystem::path& file, const RenderedImage& image, const dp::io::AovSelection& aovs,
               const std::string& software);

// 8-bit sRGB, scaled by 2^exposure_stops and clipped to [0, 1].
void write_png_preview(const std::filesystem::path& file, const Image& image, double exposure_stops,
                       const std::string& software);

// The sRGB transfer function (IEC 61966-2-1) of a linear value in [0, 1].
float linear_to_srgb(float linear);

}  // namespace dp::render
