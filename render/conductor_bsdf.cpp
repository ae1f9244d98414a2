#include "conductor_bsdf.h"

#include <cmath>

#include "fresnel.h"
#include "scattering_geometry.h"

namespace dp::render {

namespace {
// The lower side behaves as the upper one mirrored.
Vec3 upper(Vec3 w, bool flip) { return flip ? Vec3{w.x, w.y, -w.z} : w; }
}  // namespace

Rgb ConductorBsdf::reflectance(float cos_incident) const {
  return tint_ * fresnel_conductor(cos_incident, eta_, k_);
}

Rgb ConductorBsdf::albedo() const { return reflectance(1); }

std::optional<BsdfSample> ConductorBsdf::sample(Vec3 wo, float /*u_lobe*/, Sample2 u) const {
  if (wo.z == 0) return std::nullopt;
  if (specular()) return BsdfSample{{-wo.x, -wo.y, wo.z}, reflectance(std::abs(wo.z)), 1, true, 1};
  const bool flip = wo.z < 0;
  const Vec3 o = upper(wo, flip);
  const Vec3 m = distribution_.sample_visible_normal(o, u);
  const Vec3 i = reflect(o, m);
  if (i.z <= 0) return std::nullopt;
  const float density = pdf(wo, upper(i, flip));
  if (!(density > 0)) return std::nullopt;
  return BsdfSample{upper(i, flip), eval(wo, upper(i, flip)) * (i.z / density), density, false, 1};
}

Rgb ConductorBsdf::eval(Vec3 wo, Vec3 wi) const {
  if (specular() || !same_hemisphere(wo, wi)) return {};
  const bool flip = wo.z < 0;
  const Vec3 o = upper(wo, flip), i = upper(wi, flip);
  const Vec3 m = normalize(o + i);
  // Walter Eq. 20.
  return reflectance(std::abs(dot(o, m))) * (distribution_.D(m) * distribution_.G(o, i) / (4 * o.z * i.z));
}

float ConductorBsdf::pdf(Vec3 wo, Vec3 wi) const {
  if (specular() || !same_hemisphere(wo, wi)) return 0;
  const bool flip = wo.z < 0;
  const Vec3 o = upper(wo, flip), i = upper(wi, flip);
  const Vec3 m = normalize(o + i);
  return distribution_.visible_normal_pdf(o, m) / (4 * std::abs(dot(o, m)));
}

}  // namespace dp::render
