#include "image_output.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "atomic_file.h"

namespace dp::render {

namespace {

// OpenImageIO chooses the format from the name, and the temporary name's
// extension is not the final one; the format is therefore named explicitly.
template <class T>
void write_atomically_with_oiio(const std::filesystem::path& file, const char* format, OIIO::ImageSpec spec,
                                const std::vector<T>& pixels) {
  const std::filesystem::path temporary = dp::io::temporary_path_for(file);
  auto out = OIIO::ImageOutput::create(format);
  if (!out) throw std::runtime_error(file.string() + ": OpenImageIO cannot write " + format + ": " + OIIO::geterror());
  const bool written = out->open(temporary.string(), spec) &&
                       out->write_image(OIIO::TypeDesc(OIIO::BaseTypeFromC<T>::value), pixels.data()) && out->close();
  if (!written) {
    const std::string error = out->geterror();
    out.reset();
    std::filesystem::remove(temporary);
    throw std::runtime_error(file.string() + ": cannot write image: " + error);
  }
  out.reset();
  dp::io::commit_temporary(temporary, file);
}

}  // namespace

float linear_to_srgb(float v) {
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1 / 2.4f) - 0.055f;
}

void write_exr(const std::filesystem::path& file, const Image& image, const std::string& software) {
  RenderedImage only_beauty(image.width, image.height);
  only_beauty.beauty = image;
  write_exr(file, only_beauty, dp::io::AovSelection{false, false, false}, software);
}

void write_exr(const std::filesystem::path& file, const RenderedImage& image, const dp::io::AovSelection& aovs,
               const std::string& software) {
  std::vector<std::string> names{"R", "G", "B", "A"};
  if (aovs.albedo) names.insert(names.end(), {"albedo.R", "albedo.G", "albedo.B"});
  if (aovs.normal) names.insert(names.end(), {"normal.X", "normal.Y", "normal.Z"});
  if (aovs.depth) names.push_back("Z");
  const std::size_t n = image.beauty.pixels.size();
  std::vector<float> interleaved;
  interleaved.reserve(n * names.size());
  for (std::size_t i = 0; i < n; ++i) {
    const Rgb& p = image.beauty.pixels[i];
    interleaved.insert(interleaved.end(), {p.r, p.g, p.b, 1.0f});
    if (aovs.albedo) interleaved.insert(interleaved.end(), {image.albedo.pixels[i].r, image.albedo.pixels[i].g, image.albedo.pixels[i].b});
    if (aovs.normal) interleaved.insert(interleaved.end(), {image.normal.pixels[i].r, image.normal.pixels[i].g, image.normal.pixels[i].b});
    if (aovs.depth) interleaved.push_back(image.depth[i]);
  }
  OIIO::ImageSpec spec(image.beauty.width, image.beauty.height, static_cast<int>(names.size()), OIIO::TypeDesc::FLOAT);
  spec.channelnames = names;
  spec.alpha_channel = 3;
  spec.z_channel = aovs.depth ? static_cast<int>(names.size()) - 1 : -1;
  spec.attribute("compression", "zip");
  spec.attribute("Software", software);
  write_atomically_with_oiio(file, "openexr", spec, interleaved);
}

void write_png_preview(const std::filesystem::path& file, const Image& image, double exposure_stops,
                       const std::string& software) {
  const auto scale = static_cast<float>(std::exp2(exposure_stops));
  std::vector<unsigned char> rgb;
  rgb.reserve(image.pixels.size() * 3);
  for (const Rgb& p : image.pixels)
    for (int c = 0; c < 3; ++c) {
      const float encoded = linear_to_srgb(std::clamp(scale * p[c], 0.0f, 1.0f));
      rgb.push_back(static_cast<unsigned char>(std::lround(255 * encoded)));
    }
  OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:ColorSpace", "sRGB");
  spec.attribute("Software", software);
  write_atomically_with_oiio(file, "png", spec, rgb);
}

}  // namespace dp::render
