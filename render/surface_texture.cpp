#include "surface_texture.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dp::render {

namespace {

int channel_index(const OIIO::ImageSpec& spec, const std::string& name, const std::filesystem::path& file) {
  for (int c = 0; c < spec.nchannels; ++c)
    if (spec.channelnames[static_cast<std::size_t>(c)] == name) return c;
  std::string found;
  for (const std::string& n : spec.channelnames) found += (found.empty() ? "" : ", ") + n;
  throw std::runtime_error(file.string() + ": surface texture has no channel '" + name + "' (expected mass, max_mass, temperature, wetting; found " +
                           (found.empty() ? "none" : found) + ")");
}

}  // namespace

SurfaceTexture SurfaceTexture::load(const std::filesystem::path& file) {
  auto in = OIIO::ImageInput::open(file.string());
  if (!in) throw std::runtime_error(file.string() + ": cannot read surface texture: " + OIIO::geterror());
  const OIIO::ImageSpec spec = in->spec();
  const int mass = channel_index(spec, "mass", file), max_mass = channel_index(spec, "max_mass", file),
            wetting = channel_index(spec, "wetting", file);
  const std::size_t n = static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height);
  const auto channels = static_cast<std::size_t>(spec.nchannels);
  std::vector<float> all(n * channels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, all.data()))
    throw std::runtime_error(file.string() + ": cannot read surface texture: " + in->geterror());
  std::vector<float> m(n), mm(n), w(n);
  for (std::size_t i = 0; i < n; ++i) {
    m[i] = all[i * channels + static_cast<std::size_t>(mass)];
    mm[i] = all[i * channels + static_cast<std::size_t>(max_mass)];
    w[i] = all[i * channels + static_cast<std::size_t>(wetting)];
    if (!std::isfinite(m[i]) || !std::isfinite(mm[i]) || !std::isfinite(w[i]) || m[i] < 0 || mm[i] < 0)
      throw std::runtime_error(file.string() + ": texel " + std::to_string(i % static_cast<std::size_t>(spec.width)) + "," +
                               std::to_string(i / static_cast<std::size_t>(spec.width)) +
                               " holds a negative or non-finite mass, max_mass or wetting");
  }
  return SurfaceTexture(spec.width, spec.height, m, mm, w);
}

SurfaceTexture::SurfaceTexture(int width, int height, const std::vector<float>& mass, const std::vector<float>& max_mass,
                               const std::vector<float>& wetting)
    : width_(width), height_(height), texels_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {
  if (width <= 0 || height <= 0 || mass.size() != texels_.size() || max_mass.size() != texels_.size() ||
      wetting.size() != texels_.size())
    throw std::invalid_argument("surface texture: channel sizes do not match width x height");
  for (std::size_t i = 0; i < texels_.size(); ++i) {
    Texel& t = texels_[i];
    t.in_chart = max_mass[i] > 0;
    t.fog = t.in_chart ? std::clamp(mass[i] / max_mass[i], 0.0f, 1.0f) : 0.0f;
    t.wetting = std::clamp(wetting[i], 0.0f, 1.0f);
  }
}

const SurfaceTexture::Texel& SurfaceTexture::texel(int col, int row) const {
  col = std::clamp(col, 0, width_ - 1);
  row = std::clamp(row, 0, height_ - 1);
  return texels_[static_cast<std::size_t>(row) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(col)];
}

SurfaceState SurfaceTexture::at(float u, float v) const {
  // Continuous texel coordinates with texel centres at integers.
  const float x = u * static_cast<float>(width_) - 0.5f;
  const float y = (1 - v) * static_cast<float>(height_) - 0.5f;
  const int col = static_cast<int>(std::floor(x)), row = static_cast<int>(std::floor(y));
  const float fx = x - static_cast<float>(col), fy = y - static_cast<float>(row);
  const float weights[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
  const Texel* corners[4] = {&texel(col, row), &texel(col + 1, row), &texel(col, row + 1), &texel(col + 1, row + 1)};
  float total = 0, fog = 0, wetting = 0;
  for (int i = 0; i < 4; ++i) {
    if (!corners[i]->in_chart) continue;
    total += weights[i];
    fog += weights[i] * corners[i]->fog;
    wetting += weights[i] * corners[i]->wetting;
  }
  if (!(total > 0)) return {};
  return {fog / total, wetting / total};
}

}  // namespace dp::render
