#pragma once
// The wetting history texture (paper Sec. 4.3, 6.2, after Wang, Mucha &
// Turk 2005, "Water Drops on Surfaces"): 1 where a liquid particle touches a
// texel, fading as exp(-elapsed / decay time) once the texel is dry. It
// records the paths particles ran along (for rendering) and marks recently
// wetted texels, which do not condense (Sec. 6.2). The paper does not say
// when a particle touches a texel; here it is when the particle's centre
// lies on the texel's front side within the contact radius (sqrt(2) times
// the particle spacing: a particle resting at its equilibrium distance of
// one spacing from an Akinci 2012 boundary then wets a disc of radius one
// spacing, the wall area it covers in a packed layer).
#include "backend/host_device.h"
#include "sph/uniform_grid.h"

namespace dp {

struct RecordWetting {
  GridView liquid;              // this step's liquid particles
  const Vec3* texel_position;
  const Vec3* texel_normal;
  float contact_radius2;        // m^2
  float dry_factor;             // exp(-dt / decay time)
  float* wetting;

  DP_HD void operator()(std::size_t t) const {
    const Vec3 xt = texel_position[t], nt = texel_normal[t];
    bool touched = false;
    liquid.for_each_near(xt, [&](std::uint32_t i) {
      const Vec3 d = liquid.position[i] - xt;
      touched = touched || (length_squared(d) < contact_radius2 && dot(d, nt) >= 0.0f);
    });
    wetting[t] = touched ? 1.0f : wetting[t] * dry_factor;
  }
};

inline constexpr float kWettingContactSpacings = 1.41421356f;

}  // namespace dp
