#pragma once
// The liquid particles as a pressure solver reads them in each iteration:
// the step's neighbour lists with their pairs' gradient factors
// (sph/neighbor_list.h), positions at the step's start, masses and
// densities, and the rigid boundary particles (Akinci 2012 volumes). PCISPH
// and DFSPH both evaluate their pressure terms over it.
#include <cstdint>

#include "backend/host_device.h"
#include "sph/neighbor_list.h"

namespace dp {

struct ListedParticles {
  ListedPairs liquid_pairs;
  ListedPairs rigid_pairs;
  const Vec3* position;
  const Vec3* rigid_position;
  const float* liquid_mass;  // m_j = w_j m of the step (ParticleMass)
  const float* rigid_volume;
  const float* density;  // of the step's start (DFSPH reads it; PCISPH uses rho0)
  float rest_density;

  DP_HD float mass(std::uint32_t j) const { return liquid_mass[j]; }
  // gradW_ij and gradW_ib of the k-th pair in i's lists.
  DP_HD Vec3 liquid_gradient(std::size_t i, std::uint32_t k) const {
    return liquid_pairs.gradient_factor[k] * (position[i] - position[liquid_pairs.list.index[k]]);
  }
  DP_HD Vec3 rigid_gradient(std::size_t i, std::uint32_t k) const {
    return rigid_pairs.gradient_factor[k] * (position[i] - rigid_position[rigid_pairs.list.index[k]]);
  }
};

}  // namespace dp
