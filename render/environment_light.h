#pragma once
// Light arriving from infinitely far away, around the whole scene: a sky
// gradient, a constant, or an HDR lat-long map. Each can be sampled by
// direction for next-event estimation and evaluated for the paths that
// escape. World up is +y.
#include <memory>
#include <numbers>

#include "render_settings.h"
#include "rgb.h"
#include "sampling.h"
#include "vec3.h"

namespace dp::render {

struct EnvironmentSample {
  Vec3 direction;  // unit, away from the scene
  Rgb radiance;
  float pdf = 0;   // solid angle
};

class EnvironmentLight {
 public:
  virtual ~EnvironmentLight() = default;
  // Radiance arriving from `direction` (unit, pointing away from the scene).
  virtual Rgb radiance(Vec3 direction) const = 0;
  virtual EnvironmentSample sample(Sample2 u) const = 0;
  virtual float pdf(Vec3 direction) const = 0;
  // Nothing to sample: light sampling skips a black environment.
  virtual bool black() const = 0;
};

// Throws std::runtime_error naming the map file when it cannot be read.
std::unique_ptr<EnvironmentLight> make_environment(const dp::io::EnvironmentSettings& settings);

// Directions drawn uniformly over the sphere: enough for smooth environments.
Vec3 sample_uniform_sphere(Sample2 u);
inline constexpr float kUniformSpherePdf = std::numbers::inv_pi_v<float> / 4;

}  // namespace dp::render
