#pragma once
// An orthonormal basis around a surface normal. Materials work in it, so
// that cos(theta) is just a direction's z.
#include <cmath>

#include "vec3.h"

namespace dp::render {

struct ShadingFrame {
  Vec3 s, t, n;

  // Any tangent will do for isotropic materials; the helper axis is the one
  // least parallel to n, so the cross product never degenerates.
  static ShadingFrame around(Vec3 n) {
    Vec3 helper = std::abs(n.x) > 0.9f ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
    Vec3 s = normalize(cross(helper, n));
    return {s, cross(n, s), n};
  }

  Vec3 to_local(Vec3 v) const { return {dot(v, s), dot(v, t), dot(v, n)}; }
  Vec3 to_world(Vec3 v) const { return v.x * s + v.y * t + v.z * n; }
};

}  // namespace dp::render
