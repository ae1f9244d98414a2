#include "image_environment.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace dp::render {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

std::vector<Rgb> read_rgb_pixels(const std::filesystem::path& file, int* width, int* height) {
  auto in = OIIO::ImageInput::open(file.string());
  if (!in) throw std::runtime_error(file.string() + ": cannot read environment map: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  *width = spec.width;
  *height = spec.height;
  const int channels = spec.nchannels;
  std::vector<float> raw(static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height) *
                         static_cast<std::size_t>(channels));
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, raw.data()))
    throw std::runtime_error(file.string() + ": cannot read environment map: " + in->geterror());
  std::vector<Rgb> pixels(static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height));
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    const float* p = &raw[i * static_cast<std::size_t>(channels)];
    // One channel is grey; otherwise the first three are R, G, B.
    pixels[i] = channels >= 3 ? Rgb{p[0], p[1], p[2]} : Rgb::gray(p[0]);
  }
  for (const Rgb& p : pixels)
    if (!(p.r >= 0 && p.g >= 0 && p.b >= 0) || !std::isfinite(p.r + p.g + p.b))
      throw std::runtime_error(file.string() + ": environment map holds a negative or non-finite radiance");
  return pixels;
}

// Rec. 709 luminance: the sampling weight of a pixel.
float luminance(Rgb c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

}  // namespace

ImageEnvironment::ImageEnvironment(const std::filesystem::path& file, float intensity, float rotation_deg)
    : rotation_(rotation_deg / 360) {
  pixels_ = read_rgb_pixels(file, &width_, &height_);
  for (Rgb& p : pixels_) p *= intensity;
  build_distribution();
}

ImageEnvironment::ImageEnvironment(std::vector<Rgb> pixels, int width, int height, float intensity, float rotation_deg)
    : pixels_(std::move(pixels)), width_(width), height_(height), rotation_(rotation_deg / 360) {
  if (width <= 0 || height <= 0 || pixels_.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height))
    throw std::invalid_argument("environment map: pixel count does not match its size");
  for (Rgb& p : pixels_) p *= intensity;
  build_distribution();
}

void ImageEnvironment::build_distribution() {
  std::vector<float> weights(pixels_.size());
  for (int row = 0; row < height_; ++row) {
    // Solid angle of a pixel is proportional to sin(theta) at its centre row.
    const float sin_theta = std::sin(kPi * (static_cast<float>(row) + 0.5f) / static_cast<float>(height_));
    for (int col = 0; col < width_; ++col) {
      const std::size_t i = static_cast<std::size_t>(row) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(col);
      weights[i] = luminance(pixels_[i]) * sin_theta;
      black_ = black_ && is_black(pixels_[i]);
    }
  }
  distribution_ = std::make_unique<PiecewiseConstant2D>(weights, static_cast<std::size_t>(width_), static_cast<std::size_t>(height_));
}

Sample2 ImageEnvironment::direction_to_uv(Vec3 d) const {
  const float theta = std::acos(std::clamp(d.y, -1.0f, 1.0f));
  float u = 0.5f + std::atan2(d.x, -d.z) / (2 * kPi) - rotation_;
  u -= std::floor(u);
  return {u, theta / kPi};
}

Vec3 ImageEnvironment::uv_to_direction(float u, float v) const {
  const float phi = 2 * kPi * (u + rotation_ - 0.5f);
  const float theta = kPi * v;
  const float sin_theta = std::sin(theta);
  return {sin_theta * std::sin(phi), std::cos(theta), -sin_theta * std::cos(phi)};
}

const Rgb& ImageEnvironment::texel(float u, float v) const {
  const int col = std::clamp(static_cast<int>(u * static_cast<float>(width_)), 0, width_ - 1);
  const int row = std::clamp(static_cast<int>(v * static_cast<float>(height_)), 0, height_ - 1);
  return pixels_[static_cast<std::size_t>(row) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(col)];
}

Rgb ImageEnvironment::radiance(Vec3 direction) const {
  const Sample2 uv = direction_to_uv(direction);
  return texel(uv.u1, uv.u2);
}

EnvironmentSample ImageEnvironment::sample(Sample2 u) const {
  const PiecewiseConstant2D::Sample s = distribution_->sample(u);
  const float sin_theta = std::sin(kPi * s.v);
  if (!(sin_theta > 0) || !(s.pdf > 0)) return {{0, 1, 0}, {}, 0};
  // Jacobian of (u, v) -> direction: dω = 2π² sin(theta) du dv.
  return {uv_to_direction(s.u, s.v), texel(s.u, s.v), s.pdf / (2 * kPi * kPi * sin_theta)};
}

float ImageEnvironment::pdf(Vec3 direction) const {
  const Sample2 uv = direction_to_uv(direction);
  const float sin_theta = std::sin(kPi * uv.u2);
  if (!(sin_theta > 0)) return 0;
  return distribution_->pdf(uv.u1, uv.u2) / (2 * kPi * kPi * sin_theta);
}

}  // namespace dp::render
