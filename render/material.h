#pragma once
// The scattering interface every surface implements. Directions are in the
// local shading frame: z is the surface normal, pointing to the object's
// outside; wo points back along the arriving path, wi along the next one.
//
// Today's materials are all either Lambertian or perfectly specular, and
// the integrator only samples. The eval/pdf pair is what next-event
// estimation with multiple importance sampling will need, and a material
// that varies over the surface (textured roughness, GGX microfacets) will
// take the hit's texture coordinates in addition.
#include <optional>

#include "rgb.h"
#include "sampling.h"
#include "vec3.h"

namespace dp::render {

struct BsdfSample {
  Vec3 wi;
  Rgb weight;         // f * |cos(theta_i)| / pdf: the factor the path throughput takes
  float pdf = 0;      // solid-angle density; for a specular lobe, the probability of choosing it
  bool specular = false;
};

class Material {
 public:
  virtual ~Material() = default;

  // u_lobe picks among lobes (reflect or refract), u places the direction
  // within one. Nothing when the path ends here (no lobe towards wi's side).
  virtual std::optional<BsdfSample> sample(Vec3 wo, float u_lobe, Sample2 u) const = 0;
  // The BSDF value f(wo, wi); zero for specular lobes, which only sampling finds.
  virtual Rgb eval(Vec3 wo, Vec3 wi) const = 0;
  // Solid-angle density with which sample() returns wi; zero for specular lobes.
  virtual float pdf(Vec3 wo, Vec3 wi) const = 0;

  // Beer-Lambert absorption coefficient of the object's inside (1/m); zero
  // for opaque objects and clear media.
  virtual Rgb absorption_per_m() const { return {}; }
};

}  // namespace dp::render
