#pragma once
// XSPH velocity smoothing (Monaghan 1989; as artificial viscosity in
// Schechter & Bridson 2012): v_i <- v_i + eps sum_j (m_j / rho_j)(v_j - v_i) W_ij.
// Against rigid particles (velocity 0) the same term with the boundary volume
// V_b acts as wall friction. Chosen over Monaghan's artificial viscosity
// because PCISPH has no speed of sound to scale the latter with.
#include <cstdint>

#include "backend/host_device.h"
#include "sph/kernel_cubic_spline.h"
#include "sph/neighbor_list.h"
#include "sph/sum_in_list_order.h"
#include "sph/uniform_grid.h"

namespace dp {

struct ApplyXsph {
  NeighborList liquid_neighbors;
  NeighborList rigid_neighbors;
  const Vec3* position;
  const Vec3* rigid_position;
  const float* volume;  // m_j / rho_j (ParticleVolume)
  const float* rigid_volume;
  const Vec3* velocity;  // before smoothing
  CubicSplineKernel kernel;
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
      dv += liquid_term(j, kernel.W(sqrtf(r2)), vi);
    });
    rigid_neighbors.for_each(i, [&](std::uint32_t b) {
      float r2 = length_squared(xi - rigid_position[b]);
      if (r2 >= h2) return;
      dv -= rigid_term(b, kernel.W(sqrtf(r2)), vi);
    });
    smoothed[i] = vi + dv;
  }

  // The CPU's: the same sums by sum_in_list_order.h (the positions have
  // moved since the lists were made, so every pair is tested against the
  // support again).
  DP_HOST_INLINE void whole_range(std::size_t begin, std::size_t end) const {
    const float h2 = kernel.h * kernel.h;
    for (std::size_t i = begin; i < end; ++i) {
      if (!fits_in_list_order(liquid_neighbors, i) || !fits_in_list_order(rigid_neighbors, i)) {
        (*this)(i);
        continue;
      }
      const std::uint32_t liquid_first = liquid_neighbors.offset[i], liquid_count = liquid_neighbors.offset[i + 1] - liquid_first;
      const std::uint32_t rigid_first = rigid_neighbors.offset[i], rigid_count = rigid_neighbors.offset[i + 1] - rigid_first;
      const Vec3 xi = position[i], vi = velocity[i];
      Vec3 dv = vector_sum_in_list_order(Vec3{}, liquid_count, [&](std::uint32_t k) {
        const std::uint32_t j = liquid_neighbors.index[liquid_first + k];
        const float r2 = length_squared(xi - position[j]);
        return keep_if(liquid_term(j, kernel.W_selected(sqrtf(r2)), vi), (j != i) & (r2 < h2));
      });
      dv = vector_sum_in_list_order(dv, rigid_count, [&](std::uint32_t k) {
        const std::uint32_t b = rigid_neighbors.index[rigid_first + k];
        const float r2 = length_squared(xi - rigid_position[b]);
        return keep_if(-rigid_term(b, kernel.W_selected(sqrtf(r2)), vi), r2 < h2);
      });
      smoothed[i] = vi + dv;
    }
  }

 private:
  DP_HD Vec3 liquid_term(std::uint32_t j, float w, Vec3 vi) const { return (epsilon * volume[j] * w) * (velocity[j] - vi); }
  DP_HD Vec3 rigid_term(std::uint32_t b, float w, Vec3 vi) const { return (boundary_epsilon * rigid_volume[b] * w) * vi; }
};

}  // namespace dp
