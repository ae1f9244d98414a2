#pragma once
// Static particle lattices sorted into the neighbour grid, for the heat
// conduction tests (shared with the other model tests).
#include <vector>

#include "../sorted_particles.h"
#include "sph/mass_units.h"

namespace dp::heat_test {
using test::grid_around;
using test::lattice_block;
using test::sort_into;
using test::SortedSet;

// Liquid particles' masses m_j = w_j m and volumes V_j = m_j / rho_j, as
// the simulation keeps them for a step (ParticleMass, ParticleVolume).
struct MassesAndVolumes {
  std::vector<float> mass, volume;
};

inline MassesAndVolumes masses_and_volumes(const std::vector<MassUnits>& units, const std::vector<float>& density,
                                           float particle_mass) {
  MassesAndVolumes m{std::vector<float>(units.size()), std::vector<float>(units.size())};
  for (std::size_t i = 0; i < units.size(); ++i) {
    ParticleMass{units.data(), particle_mass, m.mass.data()}(i);
    ParticleVolume{m.mass.data(), density.data(), m.volume.data()}(i);
  }
  return m;
}
}  // namespace dp::heat_test
