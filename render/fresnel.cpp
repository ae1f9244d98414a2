#include "fresnel.h"

#include <cmath>

namespace dp::render {

std::optional<float> refracted_cosine(float cos_incident, float eta) {
  float sin2_incident = std::max(0.0f, 1 - cos_incident * cos_incident);
  float sin2_transmitted = sin2_incident / (eta * eta);
  if (sin2_transmitted >= 1) return std::nullopt;
  return std::sqrt(1 - sin2_transmitted);
}

FresnelReflectance fresnel_dielectric(float cos_incident, float eta) {
  std::optional<float> cos_transmitted = refracted_cosine(cos_incident, eta);
  if (!cos_transmitted) return {1, 1};
  float ci = cos_incident, ct = *cos_transmitted;
  float r_s = (ci - eta * ct) / (ci + eta * ct);
  float r_p = (eta * ci - ct) / (eta * ci + ct);
  return {r_s * r_s, r_p * r_p};
}

}  // namespace dp::render
