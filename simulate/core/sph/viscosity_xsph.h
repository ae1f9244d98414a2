#pragma once
// XSPH velocity smoothing (Monaghan 1989; as artificial viscosity in
// Schechter & Bridson 2012): v_i <- v_i + eps sum_j (m_j / rho_j)(v_j - v_i) W_ij.
// Against rigid particles (velocity 0) the same term with the boundary volume
// V_b acts as wall friction. Chosen over Monaghan's artificial viscosity
// because PCISPH has no speed of sound to scale the latter with.
#include <cstdint>

#include "backend/host_device.h"
#include "sph/kernel_cubic_spline.h"
#include "sph/mass_units.h"
#include "sph/neighbor_list.h"
#include "sph/uniform_grid.h"

namespace dp {

struct ApplyXsph {
  NeighborList liquid_neighbors;
  NeighborList rigid_neighbors;
  const Vec3* position;
  const Vec3* rigid_position;
  const MassUnits* units;
  const float* density;
  const float* rigid_volume;
  const Vec3* velocity;  // before smoothing
  CubicSplineKernel kernel;
  float particle_mass;
  float epsilon;           // between liquid particles
  float boundary_epsilon;  // against rigid particles
  Vec3* smoothed;          // after
  DP_HD void operator()(std::size_t i) const {
    const Vec3 xi = position[i], vi = velocity[i];
    const float h2 = kernel.h * kernel.h;
    Vec3 dv{};
    liquid_neighbors.for_each(i, [&](std::uint32_t j) {
      float r2 = length_squared(xi - position[j]);
      if (j == i || r2 >= h2) return;
      float volume_j = particle_mass * weight_of(units[j]) / density[j];
      dv += (epsilon * volume_j * kernel.W(sqrtf(r2))) * (velocity[j] - vi);
    });
    rigid_neighbors.for_each(i, [&](std::uint32_t b) {
      float r2 = length_squared(xi - rigid_position[b]);
      if (r2 >= h2) return;
      dv -= (boundary_epsilon * rigid_volume[b] * kernel.W(sqrtf(r2))) * vi;
    });
    smoothed[i] = vi + dv;
  }
};

}  // namespace dp
