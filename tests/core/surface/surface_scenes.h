#pragma once
// Rigid plates and texel sets for the surface-texture tests, made here
// rather than through simulate/io so that the core's tests build on a bare
// CUDA machine.
#include <array>
#include <cmath>
#include <vector>

#include "rigid/sample_surface.h"
#include "simulation.h"

namespace dp::test {

// A square plate in the plane y = height, [0, side]^2 in x and z, sampled
// into boundary particles at `spacing` (a lattice at multiples of spacing).
inline std::vector<Vec3> plate_particles(float side, float height, float spacing) {
  std::vector<std::array<float, 3>> p{{0, height, 0}, {side, height, 0}, {side, height, side}, {0, height, side}};
  std::vector<std::array<std::uint32_t, 3>> t{{0, 2, 1}, {0, 3, 2}};
  return sample_surface(p, t, spacing);
}

// Texels on the plane y = height at x, z = i * step, j * step for
// i, j in [0, count), normals +y, each of area step^2.
inline TexelGeometry lattice_texels(int count, float step, float height) {
  TexelGeometry g;
  g.width = g.height = count;
  for (int j = 0; j < count; ++j)
    for (int i = 0; i < count; ++i) {
      g.pixel.push_back(static_cast<std::uint32_t>(j * count + i));
      g.position.push_back(Vec3{i * step, height, j * step});
      g.normal.push_back(Vec3{0, 1, 0});
      g.area.push_back(step * step);
      g.max_mass.push_back(0.05f * step * step);
    }
  return g;
}

// A setup with rigid plates and no liquid; conduction off, so rigid
// temperatures stay as given.
inline SimulationSetup plate_setup(float spacing) {
  SimulationSetup s;
  s.particle_spacing = spacing;
  s.domain_min = Vec3{-0.1f, -0.1f, -0.1f};
  s.domain_max = Vec3{0.3f, 0.3f, 0.3f};
  s.heat_conduction = false;
  s.gravity = Vec3{0, 0, 0};
  return s;
}

}  // namespace dp::test
