#include "smooth_dielectric.h"

#include <cmath>

#include "fresnel.h"

namespace dp::render {

std::optional<BsdfSample> SmoothDielectric::sample(Vec3 wo, float u_lobe, Sample2 /*u*/) const {
  if (wo.z == 0) return std::nullopt;
  const bool entering = wo.z > 0;
  const float eta = entering ? ior_ : 1 / ior_;  // far side over incident side
  const float cos_incident = std::abs(wo.z);
  const float reflectance = fresnel_dielectric(cos_incident, eta).unpolarized();

  if (u_lobe < reflectance) {
    // Chosen with probability R, carrying R: the weight is 1.
    return BsdfSample{{-wo.x, -wo.y, wo.z}, Rgb::gray(1), reflectance, true};
  }
  const float cos_transmitted = *refracted_cosine(cos_incident, eta);  // R < 1, so no total reflection
  const Vec3 facing_normal{0, 0, entering ? 1.0f : -1.0f};
  const Vec3 wi = (-1 / eta) * wo + (cos_incident / eta - cos_transmitted) * facing_normal;
  // Radiance is compressed into the smaller solid angle of the denser side:
  // a path carrying radiance across the boundary scales it by 1/eta^2,
  // which cancels between entering and leaving a closed object.
  return BsdfSample{wi, Rgb::gray(1 / (eta * eta)), 1 - reflectance, true};
}

}  // namespace dp::render
