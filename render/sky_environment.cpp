#include "sky_environment.h"

#include <algorithm>
#include <cmath>

namespace dp::render {

SkyEnvironment::SkyEnvironment(const dp::io::EnvironmentSettings& s)
    : zenith_(Rgb::from(s.zenith) * static_cast<float>(s.intensity)),
      horizon_(Rgb::from(s.horizon) * static_cast<float>(s.intensity)),
      ground_(Rgb::from(s.ground) * static_cast<float>(s.intensity)) {}

Rgb SkyEnvironment::radiance(Vec3 direction) const {
  if (direction.y < 0) return ground_;
  return lerp(horizon_, zenith_, direction.y);
}

EnvironmentSample SkyEnvironment::sample(Sample2 u) const {
  const Vec3 d = sample_uniform_sphere(u);
  return {d, radiance(d), kUniformSpherePdf};
}

}  // namespace dp::render
