#include "dielectric_bsdf.h"

#include <cmath>

#include "fresnel.h"
#include "scattering_geometry.h"

namespace dp::render {

namespace {

// Fresnel reflectance at a microfacet with normal m (m.z > 0) seen from w;
// ior is the inside's index.
float fresnel_at(Vec3 w, Vec3 m, float ior) {
  const float cos_m = dot(w, m);
  return fresnel_dielectric(std::abs(cos_m), cos_m > 0 ? ior : 1 / ior).unpolarized();
}

}  // namespace

float DielectricBsdf::relative_eta(Vec3 wo, Vec3 wi) const {
  if (same_hemisphere(wo, wi)) return 1;
  return wo.z > 0 ? ior_ : 1 / ior_;
}

std::optional<BsdfSample> DielectricBsdf::sample_smooth(Vec3 wo, float u_lobe) const {
  const float eta = wo.z > 0 ? ior_ : 1 / ior_;
  const float reflectance = fresnel_dielectric(std::abs(wo.z), eta).unpolarized();
  if (u_lobe < reflectance) {
    // Chosen with probability R, carrying R: the weight is 1.
    return BsdfSample{{-wo.x, -wo.y, wo.z}, Rgb::gray(1), reflectance, true, 1};
  }
  const std::optional<Vec3> wi = refract(wo, {0, 0, 1}, ior_);  // R < 1, so no total reflection
  if (!wi) return std::nullopt;
  return BsdfSample{*wi, Rgb::gray(1 / (eta * eta)), 1 - reflectance, true, eta};
}

std::optional<BsdfSample> DielectricBsdf::sample(Vec3 wo, float u_lobe, Sample2 u) const {
  if (wo.z == 0) return std::nullopt;
  if (specular()) return sample_smooth(wo, u_lobe);
  // Walter's Sec. 5.3 with the visible-normal density in place of D(m)|m.z|:
  // pick a facet wo sees, then reflect or refract with its Fresnel weight.
  const Vec3 m = distribution_.sample_visible_normal(wo, u);
  const float reflectance = fresnel_at(wo, m, ior_);
  Vec3 wi;
  if (u_lobe < reflectance) {
    wi = reflect(wo, m);
    if (!same_hemisphere(wo, wi)) return std::nullopt;
  } else {
    const std::optional<Vec3> refracted = refract(wo, m, ior_);
    if (!refracted || same_hemisphere(wo, *refracted) || refracted->z == 0) return std::nullopt;
    wi = *refracted;
  }
  const float density = pdf(wo, wi);
  if (!(density > 0)) return std::nullopt;
  const Rgb weight = eval(wo, wi) * (std::abs(wi.z) / density);
  return BsdfSample{wi, weight, density, false, relative_eta(wo, wi)};
}

std::optional<Vec3> DielectricBsdf::half_vector(Vec3 wo, Vec3 wi) const {
  // Walter Eq. 16 (h_t = -(eta_i i + eta_o o)), written with the index
  // ratio: for refraction wo + eta wi is along the micro-normal.
  const float eta = relative_eta(wo, wi);
  Vec3 m = wo + eta * wi;
  if (length_squared(m) == 0) return std::nullopt;
  m = normalize(m);
  if (m.z < 0) m = -m;
  // A facet seen from its back by either direction scatters nothing.
  if (dot(m, wo) * wo.z <= 0 || dot(m, wi) * wi.z <= 0) return std::nullopt;
  return m;
}

Rgb DielectricBsdf::eval(Vec3 wo, Vec3 wi) const {
  if (specular() || wo.z == 0 || wi.z == 0) return {};
  const std::optional<Vec3> m = half_vector(wo, wi);
  if (!m) return {};
  const float reflectance = fresnel_at(wo, *m, ior_);
  const float D = distribution_.D(*m), G = distribution_.G(wo, wi);
  if (same_hemisphere(wo, wi)) {
    // Walter Eq. 20.
    return Rgb::gray(D * G * reflectance / std::abs(4 * wo.z * wi.z));
  }
  // Walter Eq. 21 for radiance arriving along wi and leaving along wo,
  // divided through by the square of wo's index; eta = wi's index over wo's.
  const float eta = relative_eta(wo, wi);
  const float denominator = dot(wo, *m) + eta * dot(wi, *m);
  return Rgb::gray(std::abs(dot(wi, *m) * dot(wo, *m) / (wi.z * wo.z)) * (1 - reflectance) * D * G /
                   (denominator * denominator));
}

float DielectricBsdf::pdf(Vec3 wo, Vec3 wi) const {
  if (specular() || wo.z == 0 || wi.z == 0) return 0;
  const std::optional<Vec3> m = half_vector(wo, wi);
  if (!m) return 0;
  const float reflectance = fresnel_at(wo, *m, ior_);
  // sample() draws facets visible from wo mirrored into the upper hemisphere.
  const float normal_pdf = distribution_.visible_normal_pdf(wo.z < 0 ? -wo : wo, *m);
  if (same_hemisphere(wo, wi)) {
    // dwi/dm of reflection: 1 / (4 |wo·m|) (Walter Eq. 14).
    return normal_pdf * reflectance / (4 * std::abs(dot(wo, *m)));
  }
  // dwi/dm of refraction (Walter Eq. 17).
  const float eta = relative_eta(wo, wi);
  const float denominator = dot(wo, *m) + eta * dot(wi, *m);
  return normal_pdf * (1 - reflectance) * eta * eta * std::abs(dot(wi, *m)) / (denominator * denominator);
}

}  // namespace dp::render
