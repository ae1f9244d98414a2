#pragma once
// A sky brightest (or bluest) overhead, with a uniform ground colour below
// the horizon; blended by the sine of the elevation, which keeps the sky
// smooth and puts most of the change near the horizon, as in a clear sky.
// Smooth enough that uniform sphere sampling serves it well.
#include "environment_light.h"

namespace dp::render {

class SkyEnvironment final : public EnvironmentLight {
 public:
  explicit SkyEnvironment(const dp::io::EnvironmentSettings& settings);

  Rgb radiance(Vec3 direction) const override;
  EnvironmentSample sample(Sample2 u) const override;
  float pdf(Vec3) const override { return kUniformSpherePdf; }
  bool black() const override { return is_black(zenith_) && is_black(horizon_) && is_black(ground_); }

 private:
  Rgb zenith_, horizon_, ground_;
};

// The same radiance from every direction: the white furnace.
class ConstantEnvironment final : public EnvironmentLight {
 public:
  explicit ConstantEnvironment(Rgb radiance) : radiance_(radiance) {}

  Rgb radiance(Vec3) const override { return radiance_; }
  EnvironmentSample sample(Sample2 u) const override { return {sample_uniform_sphere(u), radiance_, kUniformSpherePdf}; }
  float pdf(Vec3) const override { return kUniformSpherePdf; }
  bool black() const override { return is_black(radiance_); }

 private:
  Rgb radiance_;
};

}  // namespace dp::render
