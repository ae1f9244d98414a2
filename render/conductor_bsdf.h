#pragma once
// A metal (the mirror's coating): Fresnel reflectance of a complex index
// eta + i k, on a smooth surface or on GGX microfacets (the microfacet BRDF
// of Walter et al. 2007, Eq. 20, sampled through the visible normals of
// Heitz 2018). Reflects on both sides, so a mirror may be a single sheet.
// `tint` scales the reflectance, for coloured or dimmed coatings.
#include <optional>

#include "bsdf_sample.h"
#include "microfacet_ggx.h"
#include "sampling.h"

namespace dp::render {

class ConductorBsdf {
 public:
  ConductorBsdf(Rgb eta, Rgb k, Rgb tint, float alpha) : eta_(eta), k_(k), tint_(tint), distribution_(alpha) {}

  std::optional<BsdfSample> sample(Vec3 wo, float u_lobe, Sample2 u) const;
  Rgb eval(Vec3 wo, Vec3 wi) const;
  float pdf(Vec3 wo, Vec3 wi) const;
  bool specular() const { return distribution_.effectively_smooth(); }
  // Normal-incidence reflectance.
  Rgb albedo() const;

 private:
  Rgb reflectance(float cos_incident) const;

  Rgb eta_, k_, tint_;
  GgxDistribution distribution_;
};

}  // namespace dp::render
