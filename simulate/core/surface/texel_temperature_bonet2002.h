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
//
// Rigids are static (Sec. 4.4), so the corrected weights
// V_k W_tk / sum_k V_k W_tk are computed once, beside the texel's neighbour
// list; each step is then one weighted sum of temperatures per texel.
#include <cstdint>

#include "backend/host_device.h"
#include "sph/kernel_cubic_spline.h"
#include "sph/neighbor_list.h"

namespace dp {

// Is the particle of setup index `source` one of the rigid's particles
// [first, first + count)? (The unsigned difference wraps for those below.)
DP_HD_INLINE bool of_rigid(std::uint32_t source, std::uint32_t first, std::uint32_t count) { return source - first < count; }

// Once: the weights V_k W-bar_tk of Eq. 7 for every entry of a texel's
// neighbour list (0 for particles of another rigid). Each texel writes only
// its own slice of the list.
struct ComputeTexelWeights {
  NeighborList neighbours;             // texel -> rigid particles (sorted indices)
  const Vec3* texel_position;
  const Vec3* rigid_position;          // sorted
  const float* rigid_volume;           // V_k
  const std::uint32_t* rigid_source;   // sorted index -> index in SimulationSetup::rigid_position
  std::uint32_t rigid_first, rigid_count;  // the texel's rigid
  CubicSplineKernel kernel;
  float* weight;                       // per neighbour-list entry

  DP_HD float volume_weight(const Vec3& xt, std::uint32_t k) const {
    if (!of_rigid(rigid_source[k], rigid_first, rigid_count)) return 0.0f;
    return rigid_volume[k] * kernel.W(length(xt - rigid_position[k]));
  }

  DP_HD void operator()(std::size_t t) const {
    const Vec3 xt = texel_position[t];
    float normalisation = 0.0f;
    neighbours.for_each(t, [&](std::uint32_t k) { normalisation += volume_weight(xt, k); });
    const float inverse = normalisation > 0.0f ? 1.0f / normalisation : 0.0f;
    for (std::uint32_t e = neighbours.offset[t]; e < neighbours.offset[t + 1]; ++e)
      weight[e] = volume_weight(xt, neighbours.index[e]) * inverse;
  }
};

// Each step: T_t = sum_k (V_k W-bar_tk) T_k. A texel that no particle of its
// rigid reaches (all weights 0) keeps its temperature.
struct InterpolateTexelTemperature {
  NeighborList neighbours;
  const float* weight;               // from ComputeTexelWeights
  const float* rigid_temperature;    // T_k, sorted
  float* texel_temperature;

  DP_HD void operator()(std::size_t t) const {
    float sum = 0.0f, weights = 0.0f;
    for (std::uint32_t e = neighbours.offset[t]; e < neighbours.offset[t + 1]; ++e) {
      sum += weight[e] * rigid_temperature[neighbours.index[e]];
      weights += weight[e];
    }
    if (weights > 0.0f) texel_temperature[t] = sum;
  }
};

// value[index[i]] != seen[i] (NaN differs from everything): has a
// temperature changed since it was seen?
struct DifferentAt {
  const float* value;
  const std::uint32_t* index;
  const float* seen;
  DP_HD bool operator()(std::size_t i) const { return value[index[i]] != seen[i]; }
};

// seen[i] = value[index[i]].
struct GatherAt {
  const float* value;
  const std::uint32_t* index;
  float* seen;
  DP_HD void operator()(std::size_t i) const { seen[i] = value[index[i]]; }
};

}  // namespace dp
