#pragma once
// Fresnel equations: how much light a smooth boundary reflects.
#include <optional>

#include "rgb.h"

namespace dp::render {

struct FresnelReflectance {
  float s = 1;  // polarised perpendicular to the plane of incidence
  float p = 1;  // polarised in the plane of incidence
  // Natural light carries both polarisations equally.
  float unpolarized() const { return 0.5f * (s + p); }
};

// cos_incident: cosine of the angle to the normal on the incident side, in
// [0, 1]. eta: refractive index of the far side over that of the incident
// side. Beyond the critical angle both reflectances are 1.
FresnelReflectance fresnel_dielectric(float cos_incident, float eta);

// Cosine of the refracted direction's angle to the normal (Snell's law), or
// nothing under total internal reflection.
std::optional<float> refracted_cosine(float cos_incident, float eta);

// Unpolarised reflectance of a conductor with complex refractive index
// eta + i k (relative to the incident medium), from the same equations
// with a complex index (Born & Wolf, Principles of Optics, Sec. 14.2).
float fresnel_conductor(float cos_incident, float eta, float k);
Rgb fresnel_conductor(float cos_incident, Rgb eta, Rgb k);

}  // namespace dp::render
