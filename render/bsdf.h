#pragma once
// The scattering function at one surface point: one of the lobe models,
// chosen by the material and parameterised by the point's textures. A value
// type (no allocation per hit); calls dispatch with std::visit.
#include <optional>
#include <variant>

#include "bsdf_sample.h"
#include "conductor_bsdf.h"
#include "dielectric_bsdf.h"
#include "lambertian.h"
#include "sampling.h"

namespace dp::render {

class Bsdf {
 public:
  using Model = std::variant<LambertianBsdf, DielectricBsdf, ConductorBsdf>;
  explicit Bsdf(Model model) : model_(model) {}

  // u_lobe picks among lobes (reflect or refract), u places the direction
  // within one. Nothing when the path ends here.
  std::optional<BsdfSample> sample(Vec3 wo, float u_lobe, Sample2 u) const {
    return std::visit([&](const auto& m) { return m.sample(wo, u_lobe, u); }, model_);
  }
  // f(wo, wi); zero for specular lobes, which only sampling finds.
  Rgb eval(Vec3 wo, Vec3 wi) const {
    return std::visit([&](const auto& m) { return m.eval(wo, wi); }, model_);
  }
  // Solid-angle density with which sample() returns wi; zero for specular lobes.
  float pdf(Vec3 wo, Vec3 wi) const {
    return std::visit([&](const auto& m) { return m.pdf(wo, wi); }, model_);
  }
  // True when every lobe is a Dirac delta: light sampling cannot help.
  bool specular() const {
    return std::visit([](const auto& m) { return m.specular(); }, model_);
  }
  // The reflectance a denoiser's albedo channel wants.
  Rgb albedo() const {
    return std::visit([](const auto& m) { return m.albedo(); }, model_);
  }

 private:
  Model model_;
};

}  // namespace dp::render
