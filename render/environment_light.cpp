#include "environment_light.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "image_environment.h"
#include "sky_environment.h"

namespace dp::render {

Vec3 sample_uniform_sphere(Sample2 u) {
  const float z = 1 - 2 * u.u1;
  const float r = std::sqrt(std::max(0.0f, 1 - z * z));
  const float phi = 2 * std::numbers::pi_v<float> * u.u2;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

std::unique_ptr<EnvironmentLight> make_environment(const dp::io::EnvironmentSettings& s) {
  switch (s.type) {
    case dp::io::EnvironmentType::Sky: return std::make_unique<SkyEnvironment>(s);
    case dp::io::EnvironmentType::Constant:
      return std::make_unique<ConstantEnvironment>(Rgb::from(s.radiance) * static_cast<float>(s.intensity));
    case dp::io::EnvironmentType::Map:
      return std::make_unique<ImageEnvironment>(s.map, static_cast<float>(s.intensity), static_cast<float>(s.rotation_deg));
  }
  return nullptr;
}

}  // namespace dp::render
