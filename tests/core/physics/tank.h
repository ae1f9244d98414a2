#pragma once
// Open-top tanks of boundary particles and blocks of liquid for the physics
// validations.
#include <algorithm>
#include <cmath>
#include <vector>

#include "simulation.h"

namespace dp::test {

// Boundary particles on the floor and four walls of the box
// [0, lx] x [0, ly] x [0, lz], at about `spacing` (one layer, Akinci 2012).
inline std::vector<Vec3> open_tank(float lx, float ly, float lz, float spacing) {
  std::vector<Vec3> b;
  const int mx = static_cast<int>(std::ceil(lx / spacing)), my = static_cast<int>(std::ceil(ly / spacing));
  const int mz = static_cast<int>(std::ceil(lz / spacing));
  const float dx = lx / mx, dy = ly / my, dz = lz / mz;
  for (int k = 0; k <= mz; ++k)
    for (int i = 0; i <= mx; ++i) b.push_back(Vec3{i * dx, 0, k * dz});
  for (int j = 1; j <= my; ++j) {
    for (int i = 0; i <= mx; ++i) {
      b.push_back(Vec3{i * dx, j * dy, 0});
      b.push_back(Vec3{i * dx, j * dy, lz});
    }
    for (int k = 1; k < mz; ++k) {
      b.push_back(Vec3{0, j * dy, k * dz});
      b.push_back(Vec3{lx, j * dy, k * dz});
    }
  }
  return b;
}

// nx x ny x nz particles at `spacing`, the first at `corner`.
inline void add_block(SimulationSetup& s, Vec3 corner, int nx, int ny, int nz) {
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        s.liquid_position.push_back(corner + s.particle_spacing * Vec3{float(i), float(j), float(k)});
        s.liquid_velocity.push_back(Vec3{});
      }
}

// A block of nx x ny x nz liquid particles at spacing s in an open tank of
// inner size lx x ly x lz.
struct ColumnInTank {
  SimulationSetup setup;
  float lx, ly, lz;
};

inline ColumnInTank column_in_tank(float s, int nx, int ny, int nz) {
  ColumnInTank c;
  SimulationSetup& setup = c.setup;
  setup.particle_spacing = s;
  setup.liquid.xsph_epsilon = 0.1f;  // damps the settling; the state at rest does not depend on it
  setup.liquid.boundary_friction = 0.1f;
  // The liquid starts 1.2 spacings from the walls: at exactly one spacing a
  // single boundary layer (Akinci 2012) adds about 6 % density per wall, and
  // removing that in the first step would take a jolt.
  const float gap = 1.2f * s;
  c.lx = (nx - 1) * s + 2 * gap, c.lz = (nz - 1) * s + 2 * gap, c.ly = (ny + 6) * s;
  setup.rigid_position = open_tank(c.lx, c.ly, c.lz, s);
  add_block(setup, Vec3{gap, gap, gap}, nx, ny, nz);
  setup.domain_min = Vec3{-0.05f, -0.05f, -0.05f};
  setup.domain_max = Vec3{c.lx + 0.05f, c.ly + 0.05f, c.lz + 0.05f};
  return c;
}

inline float largest_speed(const Simulation& sim) {
  float v = 0;
  for (const Vec3& u : sim.particles().velocity) v = std::max(v, length(u));
  return v;
}

}  // namespace dp::test
