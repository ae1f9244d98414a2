#pragma once
// One scattering direction drawn from a BSDF, in the local shading frame
// (z is the surface normal, pointing to the object's outside; wo points
// back along the arriving path, wi along the next one).
#include "rgb.h"
#include "vec3.h"

namespace dp::render {

struct BsdfSample {
  Vec3 wi;
  Rgb weight;          // f * |cos(theta_i)| / pdf: the factor the path throughput takes
  float pdf = 0;       // solid-angle density; for a specular lobe, the probability of choosing it
  bool specular = false;
  // Relative index crossed: index on wi's side over index on wo's side
  // (1 for reflection). Radiance crossing it is scaled by 1/eta²,
  // which `weight` includes.
  float eta = 1;
};

inline bool same_hemisphere(Vec3 a, Vec3 b) { return a.z * b.z > 0; }

}  // namespace dp::render
