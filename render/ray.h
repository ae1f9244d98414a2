#pragma once
// A half-line from origin along a unit direction.
#include "vec3.h"

namespace dp::render {

struct Ray {
  Vec3 origin;
  Vec3 direction;
};

// A ray leaving a surface point must not hit that same surface again through
// rounding. Its origin moves off the surface by a few float steps of the
// point's magnitude, far less than any real mesh's detail at that scale.
// `departure_side` is the unit surface normal on the side the scattering
// sent the ray to; with a bent shading normal, the direction itself may
// graze the facet's other side, and the ray must then meet the facet again
// rather than tunnel through it.
inline Ray ray_leaving_surface(Vec3 point, Vec3 departure_side, Vec3 direction) {
  const float offset = 1e-5f * (1 + max_abs_component(point));
  return {point + offset * departure_side, direction};
}

}  // namespace dp::render
