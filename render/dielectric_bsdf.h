#pragma once
// The boundary to a dielectric (water, glass): Fresnel reflection and Snell
// refraction, on a perfectly smooth surface or on a rough one made of GGX
// microfacets (Walter, Marschner, Li & Torrance 2007, "Microfacet Models
// for Refraction through Rough Surfaces", Eqs. 20-21 for the BRDF and BTDF,
// Eqs. 38-41 for sampling, here through the visible normals of Heitz 2018).
// The inside (against z) has index `ior`, the outside 1. Radiance carried
// into the denser side is compressed by 1/eta² (Veach 1997, Sec. 5.2); the
// factor cancels for a path that enters and leaves a closed object.
#include <optional>

#include "bsdf_sample.h"
#include "microfacet_ggx.h"
#include "sampling.h"

namespace dp::render {

class DielectricBsdf {
 public:
  DielectricBsdf(float ior, float alpha) : ior_(ior), distribution_(alpha) {}

  std::optional<BsdfSample> sample(Vec3 wo, float u_lobe, Sample2 u) const;
  Rgb eval(Vec3 wo, Vec3 wi) const;
  float pdf(Vec3 wo, Vec3 wi) const;
  // An index of 1 lets everything through unchanged, whatever the roughness.
  bool specular() const { return ior_ == 1 || distribution_.effectively_smooth(); }
  Rgb albedo() const { return Rgb::gray(1); }

 private:
  std::optional<BsdfSample> sample_smooth(Vec3 wo, float u_lobe) const;
  // Index on wi's side over index on wo's side.
  float relative_eta(Vec3 wo, Vec3 wi) const;
  // The micro-normal that scatters wo into wi, on the outside (+z); nothing
  // for a pair no microfacet connects.
  std::optional<Vec3> half_vector(Vec3 wo, Vec3 wi) const;

  float ior_;
  GgxDistribution distribution_;
};

}  // namespace dp::render
