#include "material.h"

#include <algorithm>
#include <stdexcept>

namespace dp::render {

Material::Material(const dp::io::Material& d, bool wet_paths)
    : type_(d.type),
      albedo_(Rgb::from(d.albedo)),
      eta_(Rgb::from(d.conductor_eta)),
      k_(Rgb::from(d.conductor_k)),
      ior_(static_cast<float>(d.ior)),
      alpha_dry_(static_cast<float>(d.roughness)),
      alpha_fogged_(static_cast<float>(d.fogged_roughness)),
      alpha_wet_(static_cast<float>(d.wet_roughness)),
      wet_darkening_(static_cast<float>(d.wet_darkening)),
      wet_paths_(wet_paths),
      emission_(Rgb::from(d.emission)),
      absorption_per_m_(Rgb::from(d.absorption_per_m)) {}

float Material::roughness_at(SurfaceState s) const {
  const float fog = std::clamp(s.fog, 0.0f, 1.0f);
  float alpha = (1 - fog) * alpha_dry_ + fog * alpha_fogged_;
  if (wet_paths_) {
    const float w = std::clamp(s.wetting, 0.0f, 1.0f);
    alpha = (1 - w) * alpha + w * alpha_wet_;
  }
  return alpha;
}

Bsdf Material::bsdf_at(SurfaceState s) const {
  const float alpha = roughness_at(s);
  const float darkening = wet_paths_ ? wet_darkening_ * std::clamp(s.wetting, 0.0f, 1.0f) : 0.0f;
  const Rgb reflectance = (1 - darkening) * albedo_;
  switch (type_) {
    case dp::io::MaterialType::Diffuse: return Bsdf(LambertianBsdf(reflectance));
    case dp::io::MaterialType::Dielectric: return Bsdf(DielectricBsdf(ior_, alpha));
    case dp::io::MaterialType::Conductor: return Bsdf(ConductorBsdf(eta_, k_, reflectance, alpha));
  }
  throw std::logic_error("unknown material type");
}

}  // namespace dp::render
