#pragma once
// Ideal diffuse reflector, reflecting on both sides of the surface so that
// rigids need no consistent winding.
#include "material.h"

namespace dp::render {

class Lambertian final : public Material {
 public:
  explicit Lambertian(Rgb albedo) : albedo_(albedo) {}

  std::optional<BsdfSample> sample(Vec3 wo, float u_lobe, Sample2 u) const override;
  Rgb eval(Vec3 wo, Vec3 wi) const override;
  float pdf(Vec3 wo, Vec3 wi) const override;

 private:
  Rgb albedo_;
};

}  // namespace dp::render
