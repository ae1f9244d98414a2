#pragma once
// Warps of uniform random numbers to directions with known densities.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "vec3.h"

namespace dp::render {

struct Sample2 {
  float u1 = 0, u2 = 0;
};

// Density proportional to cos(theta) about +z, which cancels the cosine of a
// Lambertian reflector: the sample weight is just its albedo.
inline Vec3 sample_cosine_hemisphere(Sample2 u) {
  float r = std::sqrt(u.u1);
  float phi = 2 * std::numbers::pi_v<float> * u.u2;
  return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1 - u.u1))};
}

inline float cosine_hemisphere_pdf(float cos_theta) { return cos_theta * std::numbers::inv_pi_v<float>; }

}  // namespace dp::render
