#pragma once
// SPH density with adaptive masses (paper Sec. 4.1: the weighted mass
// w_j m enters the sum, so a lighter particle occupies less volume) and the
// rigid boundary's share (Akinci 2012, Eq. 6).
#include <cstdint>

#include "backend/host_device.h"
#include "math/keep_if.h"
#include "sph/kernel_cubic_spline.h"
#include "sph/mass_units.h"
#include "sph/neighbor_list.h"
#include "sph/sum_in_list_order.h"
#include "sph/uniform_grid.h"

namespace dp {

// rho(x) = sum_j w_j m W(x - x_j) + sum_b rho0 V_b W(x - x_b), at any point x.
struct DensityAt {
  GridView liquid;
  GridView rigid;
  const MassUnits* units;
  const float* rigid_volume;
  CubicSplineKernel kernel;
  float particle_mass;  // m of a full particle
  float rest_density;

  DP_HD float operator()(Vec3 x) const {
    const float h2 = kernel.h * kernel.h;
    float liquid_part = 0.0f, rigid_part = 0.0f;
    // Most candidates of the 27 cells lie outside the support: rejected on
    // the squared distance before the square root.
    liquid.for_each_near(x, [&](std::uint32_t j) {
      float r2 = length_squared(x - liquid.position[j]);
      if (r2 < h2) liquid_part += weight_of(units[j]) * kernel.W(sqrtf(r2));
    });
    rigid.for_each_near(x, [&](std::uint32_t b) {
      float r2 = length_squared(x - rigid.position[b]);
      if (r2 < h2) rigid_part += rigid_volume[b] * kernel.W(sqrtf(r2));
    });
    return particle_mass * liquid_part + rest_density * rigid_part;
  }
};

// The density of liquid particle i at `position[i]`, over the step's
// neighbour lists (i itself included in the liquid list). With the
// predicted positions this is PCISPH's predicted density; neighbours that
// moved out of the support drop out by the distance test.
struct ListedDensity {
  NeighborList liquid_neighbors;
  NeighborList rigid_neighbors;
  const Vec3* position;
  const Vec3* rigid_position;
  const MassUnits* units;
  const float* rigid_volume;
  CubicSplineKernel kernel;
  float particle_mass;
  float rest_density;

  DP_HD float operator()(std::size_t i) const {
    const Vec3 xi = position[i];
    const float h2 = kernel.h * kernel.h;
    float liquid_part = 0.0f, rigid_part = 0.0f;
    liquid_neighbors.for_each(i, [&](std::uint32_t j) {
      float r2 = length_squared(xi - position[j]);
      if (r2 < h2) liquid_part += weight_of(units[j]) * kernel.W(sqrtf(r2));
    });
    rigid_neighbors.for_each(i, [&](std::uint32_t b) {
      float r2 = length_squared(xi - rigid_position[b]);
      if (r2 < h2) rigid_part += rigid_volume[b] * kernel.W(sqrtf(r2));
    });
    return particle_mass * liquid_part + rest_density * rigid_part;
  }

  // The same value on the CPU, by sum_in_list_order.h: the kernel's pieces
  // are selected and the support test keeps or zeroes a term. operator()'s
  // one loop took a square root and a division at a time and kept its sum
  // on the stack (a store and a load on every pair's dependency chain);
  // PCISPH runs this every iteration. Lists longer than kMaxTermsInOrder
  // take operator().
  DP_HOST_INLINE float split_sum(std::size_t i) const {
    if (!fits_in_list_order(liquid_neighbors, i) || !fits_in_list_order(rigid_neighbors, i)) return (*this)(i);
    const Vec3 xi = position[i];
    const float liquid_part = sum_of_terms(liquid_neighbors, i, xi, position, [&](std::uint32_t j) { return weight_of(units[j]); });
    const float rigid_part = sum_of_terms(rigid_neighbors, i, xi, rigid_position, [&](std::uint32_t b) { return rigid_volume[b]; });
    return particle_mass * liquid_part + rest_density * rigid_part;
  }

 private:
  // sum over i's list of factor(j) W(|x_i - x_j|) within the support.
  template <class Factor>
  DP_HOST_INLINE float sum_of_terms(const NeighborList& list, std::size_t i, Vec3 xi, const Vec3* at, const Factor& factor) const {
    const std::uint32_t first = list.offset[i];
    const float h2 = kernel.h * kernel.h;
    return sum_in_list_order(0.0f, list.offset[i + 1] - first, [&](std::uint32_t k) {
      const std::uint32_t j = list.index[first + k];
      const float r2 = length_squared(xi - at[j]);
      return keep_if(factor(j) * kernel.W_selected(sqrtf(r2)), r2 < h2);
    });
  }
};

struct ComputeDensity {
  ListedDensity density_of;
  float* density;
  DP_HD void operator()(std::size_t i) const { density[i] = density_of(i); }
  DP_HOST_INLINE void whole_range(std::size_t begin, std::size_t end) const {
    for (std::size_t i = begin; i < end; ++i) density[i] = density_of.split_sum(i);
  }
};

}  // namespace dp
