#pragma once
// Small simulation setups built in code, shared by the core's tests.
#include <cmath>

#include "simulation.h"

namespace dp::test {

// A block of liquid above a square plate of boundary particles.
inline SimulationSetup block_over_plate(int nx, int ny, int nz) {
  SimulationSetup s;
  s.particle_spacing = 0.01f;
  s.time_step.mode = TimeStepMode::Fixed;
  s.time_step.max_step = 1e-3f;
  s.domain_min = Vec3{-0.2f, -0.05f, -0.2f};
  s.domain_max = Vec3{0.2f, 0.4f, 0.2f};
  const float h = s.particle_spacing;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        s.liquid_position.push_back(Vec3{(i - nx / 2) * h, 0.02f + j * h, (k - nz / 2) * h});
        s.liquid_velocity.push_back(Vec3{0.1f * std::sin(0.7f * i), 0.0f, 0.1f * std::cos(0.3f * k)});
      }
  // Every model of the step takes part: a hot plate held at 80 C under a
  // 20 C liquid (heat), tension and adhesion.
  s.liquid.surface_tension = 0.5f;
  for (int k = -12; k <= 12; ++k)
    for (int i = -12; i <= 12; ++i) {
      s.rigid_position.push_back(Vec3{i * h, 0.0f, k * h});
      s.rigid_temperature.push_back(353.15f);
      s.rigid_held.push_back(1);
      s.rigid_adhesion.push_back(2.0f);
    }
  return s;
}

}  // namespace dp::test
