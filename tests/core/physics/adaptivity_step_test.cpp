// Adaptive masses inside the step (Alg. 1 line 18): light particles merge
// with neighbours; the total mass stays exactly what it was (integer mass
// units), and no weight exceeds one.
#include <gtest/gtest.h>

#include "sph/mass_units.h"
#include "tank.h"

namespace dp {
namespace {

TEST(AdaptivityInStep, LightParticlesMergeAndMassIsExact) {
  const float s = 0.01f, gap = 1.2f * s;
  SimulationSetup setup;
  setup.particle_spacing = s;
  const float l = 7 * s + 2 * gap;
  setup.rigid_position = test::open_tank(l, 0.2f, l, s);
  test::add_block(setup, Vec3{gap, gap, gap}, 8, 6, 8);
  // Every third particle holds a fifth of a particle's mass.
  std::uint64_t total = 0;
  for (std::size_t i = 0; i < setup.liquid_position.size(); ++i) {
    setup.liquid_units.push_back(i % 3 == 0 ? kFullParticleUnits / 5 : kFullParticleUnits);
    total += setup.liquid_units.back();
  }
  setup.domain_min = Vec3{-0.05f, -0.05f, -0.05f};
  setup.domain_max = Vec3{l + 0.05f, 0.25f, l + 0.05f};
  auto sim = make_simulation(ExecutionConfig{Device::Cpu, 0}, setup);
  const std::size_t n0 = setup.liquid_position.size();
  for (int k = 0; k < 20; ++k) sim->step();
  ParticleSnapshot p = sim->particles();
  std::uint64_t after = 0;
  for (std::uint32_t u : p.mass_units) {
    after += u;
    EXPECT_LE(u, kFullParticleUnits);
    EXPECT_GT(u, 0u);
  }
  EXPECT_EQ(after, total);
  // The frame's per-step quantities belong to the same particle set.
  ASSERT_EQ(p.density.size(), p.size());
  ASSERT_EQ(p.surface_area.size(), p.size());
  ASSERT_EQ(p.pressure.size(), p.size());
  for (float rho : p.density) EXPECT_GT(rho, 0.5f * setup.liquid.rest_density);
  EXPECT_LT(p.size(), n0);
  RecordProperty("particles_before", std::to_string(n0));
  RecordProperty("particles_after", std::to_string(p.size()));
}

}  // namespace
}  // namespace dp
