// Texels -> particles (Sec. 6.2, Alg. 1 line 17): a plate whose texture
// holds several particles' worth of water per seed emits particles, and the
// water they take leaves the texels exactly.
#include <gtest/gtest.h>

#include "../surface/surface_scenes.h"

namespace dp {
namespace {

SimulationSetup wet_plate(float mass_per_area) {
  SimulationSetup s = test::plate_setup(0.01f);
  s.rigid_position = test::plate_particles(0.2f, 0.0f, 0.01f);
  SurfaceTextureSetup t;
  t.rigid_first = 0;
  t.rigid_count = s.rigid_position.size();
  t.texels = test::lattice_texels(40, 0.005f, 0.0f);
  for (std::size_t i = 0; i < t.texels.size(); ++i) t.texels.max_mass[i] = 50.0f * t.texels.area[i];
  t.initial_mass_per_area = mass_per_area;
  s.surfaces.push_back(t);
  s.time_step.mode = TimeStepMode::Fixed;
  s.time_step.max_step = 1e-3f;
  return s;
}

// liquid units * 2^32 + texel units, exactly.
__extension__ typedef unsigned __int128 Wide;
Wide water_units(const Simulation& sim) {
  Wide w = 0;
  for (MassUnits u : sim.particles().mass_units) w += static_cast<Wide>(u) << kTexelUnitShift;
  for (const SurfaceSnapshot& s : sim.surfaces())
    for (TexelMassUnits m : s.mass_units) w += m;
  return w;
}

TEST(coupling_Emission, SeedsHoldingAParticlesMassEmitOneAndTheWaterBalances) {
  // 20 kg/m^2 over a seed's ~3e-4 m^2 of texels: several 1 g particles each.
  SimulationSetup s = wet_plate(20.0f);
  auto sim = make_simulation(ExecutionConfig{Device::Cpu, 1}, s);
  const Wide before = water_units(*sim);
  sim->step();
  const ParticleSnapshot p = sim->particles();
  EXPECT_GT(p.size(), 100u);
  EXPECT_TRUE(water_units(*sim) == before);
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_NEAR(p.position[i].y, 0.01f, 1e-5f) << "one spacing above the plate";
}

TEST(coupling_Emission, LessThanAParticlePerSeedEmitsNothing) {
  SimulationSetup s = wet_plate(1.0f);  // ~3e-4 kg per seed < 1e-3 kg
  auto sim = make_simulation(ExecutionConfig{Device::Cpu, 1}, s);
  sim->step();
  EXPECT_EQ(sim->particles().size(), 0u);
}

}  // namespace
}  // namespace dp
