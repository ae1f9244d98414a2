#pragma once
// Whole simulations with air and coupling, for Phase 3's tests.
#include "simulation.h"

namespace dp::test {

// A cube of n^3 liquid particles at `kelvin` floating (no gravity) in a
// closed box of still air at 20 degC, centred in one 5 cm air cell (cells
// must be wider than 2 support radii).
inline SimulationSetup liquid_cube_in_air(int n, float kelvin, double ambient_vapor) {
  SimulationSetup s;
  s.particle_spacing = 0.01f;
  s.gravity = Vec3{0, 0, 0};
  s.time_step.mode = TimeStepMode::Fixed;
  s.time_step.max_step = 2e-3f;
  s.domain_min = Vec3{0, 0, 0};
  s.domain_max = Vec3{0.4f, 0.4f, 0.4f};
  s.liquid.temperature = kelvin;
  s.liquid.xsph_epsilon = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) s.liquid_position.push_back(Vec3{0.225f + (i - n / 2) * 0.01f, 0.225f + (j - n / 2) * 0.01f, 0.225f + (k - n / 2) * 0.01f});
  s.liquid_velocity.assign(s.liquid_position.size(), Vec3{0, 0, 0});
  AirSettings a;
  a.domain_min = s.domain_min;
  a.domain_max = s.domain_max;
  a.resolution = 8;
  a.buoyancy_alpha = 0;
  a.buoyancy_beta = 0;
  a.ambient_vapor = ambient_vapor;
  s.air = a;
  return s;
}

}  // namespace dp::test
