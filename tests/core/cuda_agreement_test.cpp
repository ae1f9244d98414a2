// CUDA against the CPU reference (label gpu). Skipped, with the reason,
// where no GPU is present.
#include <gtest/gtest.h>

#include <cmath>

#include "simulation.h"
#include "test_scenes.h"

namespace dp {
namespace {

class CudaAgreement : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string why;
    if (cuda_device_count(&why) == 0) GTEST_SKIP() << "no GPU: " << why;
  }
};

// 20 steps: rounding differences (FMA contraction on the GPU) grow with
// the dynamics' sensitivity, so a short run tests the kernels, not chaos.
void expect_backends_agree_after_20_steps(const SimulationSetup& setup) {
  auto cpu = make_simulation(ExecutionConfig{Device::Cpu, 0}, setup);
  auto gpu = make_simulation(ExecutionConfig{Device::Cuda, 0}, setup);
  for (int i = 0; i < 20; ++i) {
    cpu->step();
    gpu->step();
  }
  ParticleSnapshot a = cpu->particles(), b = gpu->particles();
  ASSERT_EQ(a.size(), b.size());
  // Both backends sort by the same keys with stable sorts, so particle order
  // agrees; values differ only by rounding (FMA contraction on the GPU).
  double max_dx = 0, max_drho = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a.id[i], b.id[i]) << "order differs at " << i;
    max_dx = std::max(max_dx, static_cast<double>(length(a.position[i] - b.position[i])));
    max_drho = std::max(max_drho, static_cast<double>(std::fabs(a.density[i] - b.density[i]) / setup.liquid.rest_density));
  }
  ::testing::Test::RecordProperty("max_position_difference_m", std::to_string(max_dx));
  EXPECT_LT(max_dx, 1e-3 * setup.particle_spacing);
  std::vector<float> ta = cpu->rigid_temperatures(), tb = gpu->rigid_temperatures();
  for (std::size_t i = 0; i < ta.size(); ++i) EXPECT_NEAR(ta[i], tb[i], 1e-3f);
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a.temperature[i], b.temperature[i], 1e-3f);
  EXPECT_LT(max_drho, 1e-4);
  std::vector<float> va = cpu->rigid_volumes(), vb = gpu->rigid_volumes();
  ASSERT_EQ(va.size(), vb.size());
  for (std::size_t i = 0; i < va.size(); ++i) EXPECT_NEAR(va[i], vb[i], 1e-6f * va[i]);
}

TEST_F(CudaAgreement, SimulationMatchesCpuAfter20Steps) {
  expect_backends_agree_after_20_steps(test::block_over_plate(12, 10, 12));
}

// Morris et al. 1997 viscosity, liquid and walls, strong enough (a thousand
// times water's) to move the particles within 20 steps.
TEST_F(CudaAgreement, ViscousSimulationMatchesCpuAfter20Steps) {
  SimulationSetup setup = test::block_over_plate(12, 10, 12);
  setup.liquid.kinematic_viscosity = 1e-3f;
  expect_backends_agree_after_20_steps(setup);
}

// Water's viscosity with Spalding's law of the wall: the block's 0.1 m/s
// along the plate at 1 cm spacing puts its first layer at y+ ~ 60, where
// the law of the wall shears about 4 times the laminar term.
TEST_F(CudaAgreement, WallLawSimulationMatchesCpuAfter20Steps) {
  SimulationSetup setup = test::block_over_plate(12, 10, 12);
  setup.liquid.kinematic_viscosity = 1e-6f;
  setup.liquid.wall_shear = WallShear::Spalding1961;
  expect_backends_agree_after_20_steps(setup);
}

// A particle thrown out of the domain leaves the shot on both backends alike
// (simulation.domain.leaving: remove).
TEST_F(CudaAgreement, RemovalOfALeavingParticleMatchesCpuAfter20Steps) {
  SimulationSetup setup = test::block_over_plate(12, 10, 12);
  setup.liquid_position[0] = Vec3{0.1999f, 0.2f, 0.0f};
  setup.liquid_velocity[0] = Vec3{4.0f, 0, 0};
  setup.leaving = DomainLeaving::Remove;
  expect_backends_agree_after_20_steps(setup);
}

// Divergence-free SPH (Bender & Koschier 2017): both solves on both backends.
TEST_F(CudaAgreement, DfsphSimulationMatchesCpuAfter20Steps) {
  SimulationSetup setup = test::block_over_plate(12, 10, 12);
  setup.pressure.method = PressureSolverMethod::Dfsph;
  expect_backends_agree_after_20_steps(setup);
}

}  // namespace
}  // namespace dp
