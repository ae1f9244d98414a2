#include "lambertian.h"

#include <cmath>
#include <numbers>

namespace dp::render {

std::optional<BsdfSample> LambertianBsdf::sample(Vec3 wo, float /*u_lobe*/, Sample2 u) const {
  if (wo.z == 0) return std::nullopt;
  Vec3 wi = sample_cosine_hemisphere(u);
  if (wo.z < 0) wi.z = -wi.z;
  // f * cos / pdf = (albedo / pi) * cos / (cos / pi)
  return BsdfSample{wi, albedo_, cosine_hemisphere_pdf(std::abs(wi.z)), false, 1};
}

Rgb LambertianBsdf::eval(Vec3 wo, Vec3 wi) const {
  return same_hemisphere(wo, wi) ? std::numbers::inv_pi_v<float> * albedo_ : Rgb{};
}

float LambertianBsdf::pdf(Vec3 wo, Vec3 wi) const {
  return same_hemisphere(wo, wi) ? cosine_hemisphere_pdf(std::abs(wi.z)) : 0.0f;
}

}  // namespace dp::render
