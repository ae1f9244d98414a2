#include "max_mass_texture.h"

#include <algorithm>
#include <stdexcept>

#include "data_image.h"

namespace dp::io {

void set_constant_max_mass(TexelGeometry& texels, double kg_per_m2) {
  for (std::size_t t = 0; t < texels.size(); ++t) texels.max_mass[t] = static_cast<float>(kg_per_m2 * texels.area[t]);
}

void set_max_mass_from_image(TexelGeometry& texels, const std::filesystem::path& image, double kg_per_m2_at_one) {
  DataImage on_atlas;
  try {
    on_atlas = resample(read_data_image(image), texels.width, texels.height);
  } catch (const std::exception& e) {
    const std::string what = e.what();
    if (what.rfind(image.string(), 0) == 0) throw;
    throw std::runtime_error(image.string() + ": cannot use it as the max-mass image: " + what);
  }
  for (std::size_t t = 0; t < texels.size(); ++t) {
    // Image row 0 is the top, as is texture row 0. Filters with negative
    // lobes can undershoot at sharp edges; a texel never holds less than 0.
    const double value = std::max(0.0f, on_atlas.values[texels.pixel[t]]);
    texels.max_mass[t] = static_cast<float>(value * kg_per_m2_at_one * texels.area[t]);
  }
}

}  // namespace dp::io
