#include "max_mass_texture.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace dp::io {

void set_constant_max_mass(TexelGeometry& texels, double kg_per_m2) {
  for (std::size_t t = 0; t < texels.size(); ++t) texels.max_mass[t] = static_cast<float>(kg_per_m2 * texels.area[t]);
}

void set_max_mass_from_image(TexelGeometry& texels, const std::filesystem::path& image, double kg_per_m2_at_one) {
  OIIO::ImageBuf source(image.string());
  if (!source.read(0, 0, true, OIIO::TypeDesc::FLOAT))
    throw std::runtime_error(image.string() + ": cannot read the max-mass image: " + source.geterror());
  const int channels = source.nchannels();
  // Resampled with OpenImageIO's filtered resize, so an image of any size
  // maps onto the atlas without aliasing.
  OIIO::ImageBuf resized = OIIO::ImageBufAlgo::resize(source, "", 0, OIIO::ROI(0, texels.width, 0, texels.height, 0, 1, 0, channels));
  if (resized.has_error())
    throw std::runtime_error(image.string() + ": cannot resample the max-mass image: " + resized.geterror());
  std::vector<float> pixels(static_cast<std::size_t>(texels.width) * texels.height * channels);
  resized.get_pixels(OIIO::ROI(0, texels.width, 0, texels.height, 0, 1, 0, channels), OIIO::TypeDesc::FLOAT, pixels.data());
  for (std::size_t t = 0; t < texels.size(); ++t) {
    const float* p = &pixels[static_cast<std::size_t>(texels.pixel[t]) * channels];
    // Image row 0 is the top, as is texture row 0.
    const double value = channels >= 3 ? 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2] : p[0];
    // Filters with negative lobes can undershoot at sharp edges.
    texels.max_mass[t] = static_cast<float>(std::max(0.0, value) * kg_per_m2_at_one * texels.area[t]);
  }
}

}  // namespace dp::io
