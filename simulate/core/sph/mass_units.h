#pragma once
// Adaptive particle masses (paper Sec. 4.1): a liquid particle carries the
// mass w_i m with weight w_i in (0, 1] and m = rho0 spacing^3. The weight is
// stored as an integer count of mass units, kFullParticleUnits to a full
// particle, so that merging, redistribution, evaporation and condensation
// move whole units: mass is conserved exactly, and sums of mass over
// particles are exact and independent of summation order (DESIGN §6).
#include <cstddef>
#include <cstdint>

#include "backend/host_device.h"

namespace dp {

using MassUnits = std::uint32_t;

inline constexpr MassUnits kFullParticleUnits = 1u << 24;

DP_HD inline float weight_of(MassUnits units) { return static_cast<float>(units) * (1.0f / kFullParticleUnits); }

// m_i = w_i m of every particle, once a step: the pressure solvers read
// m_j for every pair of every iteration, where it took a conversion and two
// products a pair. The same floats as particle_mass * weight_of(units).
struct ParticleMass {
  const MassUnits* units;
  float particle_mass;  // m of a full particle
  float* mass;
  DP_HD void operator()(std::size_t i) const { mass[i] = particle_mass * weight_of(units[i]); }
};

// V_i = m_i / rho_i once a step, for the sums that weigh each neighbour by
// its volume. The same floats as particle_mass * weight_of(units) / density.
struct ParticleVolume {
  const float* mass;
  const float* density;
  float* volume;
  DP_HD void operator()(std::size_t i) const { volume[i] = mass[i] / density[i]; }
};

}  // namespace dp
