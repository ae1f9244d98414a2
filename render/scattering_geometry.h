#pragma once
// Mirror and Snell directions about a (micro-)normal, in any frame.
#include <cmath>
#include <optional>

#include "vec3.h"

namespace dp::render {

// wo mirrored about n: the reflected direction, on wo's side of n.
inline Vec3 reflect(Vec3 wo, Vec3 n) { return -wo + 2 * dot(wo, n) * n; }

// The direction refracted from wo through a boundary with normal n, where
// eta is the index on the far side of n over the index on wo's side when
// wo·n > 0 (the roles swap when wo is on n's other side). Nothing under
// total internal reflection.
inline std::optional<Vec3> refract(Vec3 wo, Vec3 n, float eta) {
  float cos_i = dot(wo, n);
  if (cos_i < 0) {
    eta = 1 / eta;
    cos_i = -cos_i;
    n = -n;
  }
  const float sin2_t = std::max(0.0f, 1 - cos_i * cos_i) / (eta * eta);
  if (sin2_t >= 1) return std::nullopt;
  const float cos_t = std::sqrt(1 - sin2_t);
  return (-1 / eta) * wo + (cos_i / eta - cos_t) * n;
}

}  // namespace dp::render
