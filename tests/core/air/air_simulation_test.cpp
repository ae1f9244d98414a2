// The air phase inside the simulation step (Alg. 1 Phase 2): cells are
// classified from the step's particles, the report carries the grid's time
// and projection figures, and the vapor ledger balances.
#include <gtest/gtest.h>

#include "../test_scenes.h"
#include "simulation.h"

namespace dp {
namespace {

AirSettings air_over_plate(const SimulationSetup& s) {
  AirSettings a;
  a.domain_min = s.domain_min;
  a.domain_max = s.domain_max;
  a.resolution = 9;  // 0.45 m / 9 = 5 cm > 2 h = 4 cm
  a.ambient_vapor = 0.008;
  a.open_face[static_cast<int>(AirFace::YMax)] = true;
  AirInflow in;
  in.box_min = Vec3{-0.2f, 0.25f, -0.2f};
  in.box_max = Vec3{-0.14f, 0.35f, 0.2f};
  in.velocity = Vec3{1.0f, 0.0f, 0.0f};
  in.temperature = 313.15f;
  in.vapor = 0.03;
  a.inflows.push_back(in);
  return a;
}

TEST(air_Simulation, StepRunsTheAirPhaseAndReportsIt) {
  SimulationSetup setup = test::block_over_plate(8, 6, 8);
  setup.air = air_over_plate(setup);
  auto sim = make_simulation(ExecutionConfig{Device::Cpu, 1}, setup);
  for (int n = 0; n < 10; ++n) sim->step();
  const StepReport& r = sim->last_step();
  EXPECT_GT(r.seconds_grid, 0.0);
  EXPECT_GT(r.air.projection_iterations, 0);
  EXPECT_LE(r.air.projection_residual, setup.air->projection_tolerance);
  const std::optional<AirSnapshot> air = sim->air();
  ASSERT_TRUE(air.has_value());
  int counts[4] = {0, 0, 0, 0};
  for (auto k : air->kind) ++counts[k];
  EXPECT_GT(counts[kSolidCell], 0) << "the plate's cells";
  EXPECT_GT(counts[kLiquidCell], 0) << "the block's cells";
  EXPECT_GT(counts[kInflowCell], 0);
  // The plate (y = 0) makes its row of cells solid; the row above holds liquid.
  const MacGrid& g = air->grid;
  int i = static_cast<int>((0.0f - g.origin.x) / g.dx), j = static_cast<int>((0.06f - g.origin.y) / g.dx),
      k = static_cast<int>((0.0f - g.origin.z) / g.dx);
  EXPECT_EQ(air->kind[g.cell(i, j, k)], kLiquidCell);
  EXPECT_NEAR(air->vapor_mass(), air->ledger.expected_mass(), 1e-9 * air->vapor_mass());
  EXPECT_GT(air->ledger.inflow_gain, 0.0);
}

TEST(air_Simulation, NoAirSectionMeansNoGridAndNoGridTime) {
  auto sim = make_simulation(ExecutionConfig{Device::Cpu, 1}, test::block_over_plate(6, 4, 6));
  sim->step();
  EXPECT_FALSE(sim->air().has_value());
  EXPECT_EQ(sim->last_step().seconds_grid, 0.0);
}

TEST(air_Simulation, CellsNotLargerThanTwoSupportRadiiAreRefused) {
  SimulationSetup setup = test::block_over_plate(6, 4, 6);
  setup.air = air_over_plate(setup);
  setup.air->resolution = 12;  // 3.75 cm < 4 cm
  try {
    make_simulation(ExecutionConfig{Device::Cpu, 1}, setup);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("at most 11 cells"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace dp
