// An unstable run stops with the step, the quantity and the particle.
#include <gtest/gtest.h>

#include <limits>

#include "simulation.h"
#include "test_scenes.h"

namespace dp {
namespace {

TEST(Instability, NonFiniteVelocityNamesStepQuantityAndParticle) {
  SimulationSetup setup = test::block_over_plate(4, 4, 4);
  setup.liquid_velocity[5].y = std::numeric_limits<float>::quiet_NaN();
  auto sim = make_simulation(ExecutionConfig{Device::Cpu, 2}, setup);
  try {
    sim->step();
    FAIL() << "expected InstabilityError";
  } catch (const InstabilityError& e) {
    EXPECT_EQ(e.step, 1);
    EXPECT_EQ(e.quantity, "non-finite position or velocity");
    EXPECT_NE(std::string(e.what()).find("step 1"), std::string::npos) << e.what();
  }
}

TEST(Instability, RunawaySpeedIsReported) {
  SimulationSetup setup = test::block_over_plate(4, 4, 4);
  setup.max_speed = 5.0f;
  setup.liquid_velocity[9] = Vec3{0, 6.0f, 0};
  auto sim = make_simulation(ExecutionConfig{Device::Cpu, 1}, setup);
  try {
    sim->step();
    FAIL() << "expected InstabilityError";
  } catch (const InstabilityError& e) {
    EXPECT_EQ(e.quantity, "speed");
    EXPECT_EQ(e.particle_id, 9u);
  }
}

TEST(Instability, LeavingTheDomainIsReported) {
  SimulationSetup setup = test::block_over_plate(4, 4, 4);
  setup.liquid_position[0] = Vec3{0.1999f, 0.2f, 0.0f};
  setup.liquid_velocity[0] = Vec3{4.0f, 0, 0};
  auto sim = make_simulation(ExecutionConfig{Device::Cpu, 1}, setup);
  EXPECT_THROW(sim->step(), InstabilityError);
}

TEST(CudaDevice, AskingForCudaWithoutAGpuIsAClearError) {
  std::string why;
  if (cuda_device_count(&why) > 0) GTEST_SKIP() << "a CUDA GPU is present; this test covers machines without one";
  SimulationSetup setup = test::block_over_plate(2, 2, 2);
  try {
    make_simulation(ExecutionConfig{Device::Cuda, 0}, setup);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("--device cuda"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace dp
