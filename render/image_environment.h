#pragma once
// An HDR environment map in lat-long (equirectangular) layout: row 0 looks
// straight up (+y), the last row straight down; the image's horizontal
// centre looks along -z and u grows towards +x (docs/scene-format.md).
// Each pixel is radiance over its patch of directions. Directions are drawn
// with density proportional to pixel luminance times the patch's solid
// angle (pbrt-v4 Sec. 12.5.2), so a small bright sun is found by light
// sampling instead of by chance.
#include <filesystem>
#include <vector>

#include "environment_light.h"
#include "piecewise_constant.h"

namespace dp::render {

class ImageEnvironment final : public EnvironmentLight {
 public:
  // rotation_deg turns the map about +y. Throws std::runtime_error naming
  // the file when it cannot be read.
  ImageEnvironment(const std::filesystem::path& file, float intensity, float rotation_deg);
  // From pixels already in memory (width * height, rows from the top).
  ImageEnvironment(std::vector<Rgb> pixels, int width, int height, float intensity, float rotation_deg);

  Rgb radiance(Vec3 direction) const override;
  EnvironmentSample sample(Sample2 u) const override;
  float pdf(Vec3 direction) const override;
  bool black() const override { return black_; }

  // Map coordinates in [0,1)² of a direction, and back.
  Sample2 direction_to_uv(Vec3 direction) const;
  Vec3 uv_to_direction(float u, float v) const;

 private:
  void build_distribution();
  const Rgb& texel(float u, float v) const;

  std::vector<Rgb> pixels_;
  int width_ = 0, height_ = 0;
  float rotation_ = 0;  // as a fraction of a full turn
  bool black_ = true;
  std::unique_ptr<PiecewiseConstant2D> distribution_;
};

}  // namespace dp::render
