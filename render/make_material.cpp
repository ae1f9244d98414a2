#include "make_material.h"

#include <stdexcept>

#include "lambertian.h"
#include "smooth_conductor.h"
#include "smooth_dielectric.h"

namespace dp::render {

std::unique_ptr<Material> make_material(const dp::io::Material& m) {
  switch (m.type) {
    case dp::io::MaterialType::Diffuse: return std::make_unique<Lambertian>(Rgb::from(m.albedo));
    case dp::io::MaterialType::Dielectric:
      return std::make_unique<SmoothDielectric>(static_cast<float>(m.ior), Rgb::from(m.absorption_per_m));
    case dp::io::MaterialType::Conductor: return std::make_unique<SmoothConductor>(Rgb::from(m.albedo));
  }
  throw std::invalid_argument("unknown material type");
}

}  // namespace dp::render
