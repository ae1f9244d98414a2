#pragma once
// Ideal diffuse reflector (Lambert), reflecting on both sides of the surface
// so that rigids need no consistent winding.
#include <optional>

#include "bsdf_sample.h"
#include "sampling.h"

namespace dp::render {

class LambertianBsdf {
 public:
  explicit LambertianBsdf(Rgb albedo) : albedo_(albedo) {}

  std::optional<BsdfSample> sample(Vec3 wo, float u_lobe, Sample2 u) const;
  Rgb eval(Vec3 wo, Vec3 wi) const;
  float pdf(Vec3 wo, Vec3 wi) const;
  bool specular() const { return false; }
  Rgb albedo() const { return albedo_; }

 private:
  Rgb albedo_;
};

}  // namespace dp::render
