#pragma once
// A perfectly smooth boundary to a dielectric (water, glass): Fresnel
// reflection and Snell refraction, one lobe chosen per sample with the
// Fresnel probability. The inside (against the normal) has index `ior`,
// the outside 1; light travelling inside is absorbed (Beer-Lambert).
#include "material.h"

namespace dp::render {

class SmoothDielectric final : public Material {
 public:
  SmoothDielectric(float ior, Rgb absorption_per_m) : ior_(ior), absorption_per_m_(absorption_per_m) {}

  std::optional<BsdfSample> sample(Vec3 wo, float u_lobe, Sample2 u) const override;
  Rgb eval(Vec3, Vec3) const override { return {}; }
  float pdf(Vec3, Vec3) const override { return 0; }
  Rgb absorption_per_m() const override { return absorption_per_m_; }

 private:
  float ior_;
  Rgb absorption_per_m_;
};

}  // namespace dp::render
