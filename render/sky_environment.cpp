#include "sky_environment.h"

namespace dp::render {

SkyEnvironment::SkyEnvironment(const dp::io::EnvironmentSettings& s)
    : zenith_(Rgb::from(s.zenith) * static_cast<float>(s.intensity)),
      horizon_(Rgb::from(s.horizon) * static_cast<float>(s.intensity)),
      ground_(Rgb::from(s.ground) * static_cast<float>(s.intensity)) {}

Rgb SkyEnvironment::radiance(Vec3 direction) const {
  if (direction.y < 0) return ground_;
  // Blending by the sine of the elevation keeps the sky smooth and puts most
  // of the change near the horizon, as in a clear sky.
  return lerp(horizon_, zenith_, direction.y);
}

}  // namespace dp::render
