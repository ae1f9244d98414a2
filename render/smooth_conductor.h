#pragma once
// A perfect mirror tinted by its albedo. Metals' angle-dependent Fresnel
// reflectance is not modelled yet: the albedo holds at every angle.
#include "material.h"

namespace dp::render {

class SmoothConductor final : public Material {
 public:
  explicit SmoothConductor(Rgb albedo) : albedo_(albedo) {}

  std::optional<BsdfSample> sample(Vec3 wo, float, Sample2) const override {
    if (wo.z == 0) return std::nullopt;
    return BsdfSample{{-wo.x, -wo.y, wo.z}, albedo_, 1, true};
  }
  Rgb eval(Vec3, Vec3) const override { return {}; }
  float pdf(Vec3, Vec3) const override { return 0; }

 private:
  Rgb albedo_;
};

}  // namespace dp::render
