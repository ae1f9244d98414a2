#include "test_textures.h"

#include <OpenImageIO/imageio.h>

#include <stdexcept>

namespace dp::render::test {

namespace {
void write_float_exr(const std::filesystem::path& file, OIIO::ImageSpec spec, const std::vector<float>& interleaved) {
  auto out = OIIO::ImageOutput::create(file.string());
  if (!out || !out->open(file.string(), spec) || !out->write_image(OIIO::TypeDesc::FLOAT, interleaved.data()) || !out->close())
    throw std::runtime_error(file.string() + ": cannot write test image");
}
}  // namespace

void write_surface_exr(const std::filesystem::path& file, int width, int height, const std::vector<float>& mass,
                       const std::vector<float>& max_mass, const std::vector<float>& wetting) {
  OIIO::ImageSpec spec(width, height, 4, OIIO::TypeDesc::FLOAT);
  spec.channelnames = {"mass", "max_mass", "temperature", "wetting"};
  std::vector<float> interleaved;
  for (std::size_t i = 0; i < mass.size(); ++i) interleaved.insert(interleaved.end(), {mass[i], max_mass[i], 290.0f, wetting[i]});
  write_float_exr(file, spec, interleaved);
}

void write_rgb_exr(const std::filesystem::path& file, int width, int height, const std::vector<Rgb>& pixels) {
  OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::FLOAT);
  std::vector<float> interleaved;
  for (const Rgb& p : pixels) interleaved.insert(interleaved.end(), {p.r, p.g, p.b});
  write_float_exr(file, spec, interleaved);
}

}  // namespace dp::render::test
