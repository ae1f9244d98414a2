#pragma once
// Rigid particles -> texel temperatures (paper Sec. 5.2, Alg. 1 line 14) by
// the corrected SPH interpolation of Eq. 7 (Bonet & Kulasegaram 2002,
// "Correction and stabilization of smooth particle hydrodynamics methods
// with applications in metal forming simulations", zeroth-order correction):
//   T_t = sum_k T_k V_k W_tk / sum_k V_k W_tk,
// over the rigid particles k of the texel's own rigid, with the Akinci 2012
// boundary volumes V_k. The normalisation makes a constant field exact
// wherever any particle is in reach, including at edges and corners where
// the plain sum of Eq. 6 would see a truncated kernel. Textures do not take
// part in conduction (Sec. 5.2): this is an interpolation, not a flux.
#include <cstdint>

#include "backend/host_device.h"
#include "sph/kernel_cubic_spline.h"
#include "sph/neighbor_list.h"

namespace dp {

// One texel per call; gathers over its precomputed rigid neighbours and
// writes only its own temperature. A texel that no particle of its rigid
// reaches keeps its temperature.
struct InterpolateTexelTemperature {
  NeighborList neighbours;           // texel -> rigid particles (sorted indices), computed once
  const Vec3* texel_position;
  const Vec3* rigid_position;        // sorted
  const float* rigid_volume;         // V_k
  const float* rigid_temperature;    // T_k
  const std::uint32_t* rigid_source; // sorted index -> index in SimulationSetup::rigid_position
  std::uint32_t rigid_first, rigid_count;  // the texel's rigid
  CubicSplineKernel kernel;
  float* texel_temperature;

  DP_HD void operator()(std::size_t t) const {
    const Vec3 xt = texel_position[t];
    float weighted = 0.0f, normalisation = 0.0f;
    neighbours.for_each(t, [&](std::uint32_t k) {
      if (rigid_source[k] - rigid_first >= rigid_count) return;  // another rigid (unsigned wrap rejects below)
      const float vw = rigid_volume[k] * kernel.W(length(xt - rigid_position[k]));
      weighted += vw * rigid_temperature[k];
      normalisation += vw;
    });
    if (normalisation > 0.0f) texel_temperature[t] = weighted / normalisation;
  }
};

}  // namespace dp
