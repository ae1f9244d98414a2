// Phase 3 on CUDA against the CPU reference (label gpu); skipped, with the
// reason, where no GPU is present.
#include <gtest/gtest.h>

#include <cmath>

#include "coupled_scenes.h"

namespace dp {
namespace {

TEST(coupling_Cuda, AgreesWithCpuAndBothLedgersClose) {
  std::string why;
  if (cuda_device_count(&why) == 0) GTEST_SKIP() << "no GPU: " << why;
  SimulationSetup s = test::liquid_cube_in_air(4, 363.15f, 0.0);
  s.coupling.coefficients.a *= 1000;
  auto cpu = make_simulation(ExecutionConfig{Device::Cpu, 0}, s);
  auto gpu = make_simulation(ExecutionConfig{Device::Cuda, 0}, s);
  for (int i = 0; i < 20; ++i) {
    cpu->step();
    gpu->step();
  }
  const WaterLedger a = cpu->water_ledger(), b = gpu->water_ledger();
  EXPECT_LT(std::fabs(a.relative_drift()), 1e-9);
  EXPECT_LT(std::fabs(b.relative_drift()), 1e-9);
  // Stochastic rounding flips where rates differ by float rounding (FMA),
  // so the transfers agree to a few units per particle, not bit for bit.
  EXPECT_NEAR(a.liquid_kg, b.liquid_kg, 1e-3 * (a.initial_kg - a.liquid_kg) + 64 * 64 * s.particle_mass() / kFullParticleUnits);
  const AirSnapshot x = *cpu->air(), y = *gpu->air();
  ASSERT_EQ(x.temperature.size(), y.temperature.size());
  for (std::size_t c = 0; c < x.temperature.size(); ++c) EXPECT_NEAR(x.temperature[c], y.temperature[c], 1e-3f) << c;
  const ParticleSnapshot p = cpu->particles(), q = gpu->particles();
  ASSERT_EQ(p.size(), q.size());
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_NEAR(p.temperature[i], q.temperature[i], 1e-3f);
}

}  // namespace
}  // namespace dp
