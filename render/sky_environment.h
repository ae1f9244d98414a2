#pragma once
// The scene's only light: a sky surrounding everything, brightest (or
// bluest) overhead, with a uniform ground colour below the horizon.
// World up is +y, the direction gravity points away from in scene files.
#include "rgb.h"
#include "scene.h"
#include "vec3.h"

namespace dp::render {

class SkyEnvironment {
 public:
  explicit SkyEnvironment(const dp::io::EnvironmentSettings& settings);

  // Radiance arriving from `direction` (unit, pointing away from the scene).
  Rgb radiance(Vec3 direction) const;

 private:
  Rgb zenith_, horizon_, ground_;
};

}  // namespace dp::render
