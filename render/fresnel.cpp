#include "fresnel.h"

#include <algorithm>
#include <cmath>
#include <complex>

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

float fresnel_conductor(float cos_incident, float eta, float k) {
  using C = std::complex<float>;
  const float ci = std::clamp(cos_incident, 0.0f, 1.0f);
  const C n(eta, k);
  // n cos(theta_t), which stays well-defined for a complex index.
  const C n_cos_t = std::sqrt(n * n - C(1 - ci * ci));
  const C r_s = (ci - n_cos_t) / (ci + n_cos_t);
  const C r_p = (n * n * ci - n_cos_t) / (n * n * ci + n_cos_t);
  return 0.5f * (std::norm(r_s) + std::norm(r_p));
}

Rgb fresnel_conductor(float cos_incident, Rgb eta, Rgb k) {
  return {fresnel_conductor(cos_incident, eta.r, k.r), fresnel_conductor(cos_incident, eta.g, k.g),
          fresnel_conductor(cos_incident, eta.b, k.b)};
}

}  // namespace dp::render
