// A column of liquid at rest in a tank (Akinci 2012 boundaries, PCISPH).
// References: incompressibility (density error below eta) and hydrostatics,
// p(d) = rho0 g d at depth d below the free surface.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "tank.h"

namespace dp {
namespace {

using test::column_in_tank;
using test::ColumnInTank;
using test::largest_speed;

// Run for PCISPH as published (each solve from zero), warm-started, and
// for DFSPH.
void check_settled_column_is_incompressible_and_hydrostatic(bool warm_start,
                                                           PressureSolverMethod method = PressureSolverMethod::Pcisph) {
  const float s = 0.01f;
  ColumnInTank column = column_in_tank(s, 8, 24, 8);
  column.setup.pressure.warm_start = warm_start;
  column.setup.pressure.method = method;
  const SimulationSetup& setup = column.setup;
  const float lx = column.lx, lz = column.lz;

  auto sim = make_simulation(ExecutionConfig{Device::Cpu, 0}, setup);
  sim->advance_to(1.5);
  ParticleSnapshot p = sim->particles();

  // Incompressible: the solver's last average density error is below eta.
  EXPECT_LT(sim->last_step().density_error, setup.pressure.max_density_error);
  ::testing::Test::RecordProperty("density_error", std::to_string(sim->last_step().density_error));

  // No particle left the tank.
  for (const Vec3& x : p.position) {
    ASSERT_GT(x.x, 0.0f);
    ASSERT_GT(x.y, 0.0f);
    ASSERT_GT(x.z, 0.0f);
    ASSERT_LT(x.x, lx);
    ASSERT_LT(x.z, lz);
  }

  // The free surface: half a spacing above the mean height of the top layer.
  float top = 0;
  for (const Vec3& x : p.position) top = std::max(top, x.y);
  double layer = 0;
  int count = 0;
  for (const Vec3& x : p.position)
    if (x.y > top - 0.5f * s) layer += x.y, ++count;
  const double surface = layer / count + 0.5 * s;

  // Pressure against depth in horizontal slabs one spacing thick in the
  // lower two thirds of the column, away from the lateral walls, averaged
  // over 0.1 s of steps as a gauge would.
  const double g = 9.81, rho0 = setup.liquid.rest_density;
  std::vector<double> slab_y;
  for (double y = 2 * s; y < surface - surface / 3; y += s) slab_y.push_back(y);
  std::vector<double> sum_p(slab_y.size(), 0), sum_depth(slab_y.size(), 0), samples(slab_y.size(), 0);
  const double end = sim->time() + 0.1;
  while (sim->time() < end) {
    sim->step();
    p = sim->particles();
    for (std::size_t k = 0; k < slab_y.size(); ++k)
      for (std::size_t i = 0; i < p.size(); ++i) {
        const Vec3 x = p.position[i];
        if (std::fabs(x.y - slab_y[k]) > 0.5 * s) continue;
        if (x.x < 2.5f * s || x.x > lx - 2.5f * s || x.z < 2.5f * s || x.z > lz - 2.5f * s) continue;
        sum_p[k] += p.pressure[i];
        sum_depth[k] += surface - x.y;
        samples[k] += 1;
      }
  }
  std::vector<double> depths, pressures;
  for (std::size_t k = 0; k < slab_y.size(); ++k) {
    if (samples[k] < 40) continue;
    depths.push_back(sum_depth[k] / samples[k]);
    pressures.push_back(sum_p[k] / samples[k]);
  }
  ASSERT_GE(depths.size(), 10u);
  // Issue #3: p(d) = rho0 g d within 5 %. Slab means still scatter by a
  // few per cent as the particle layers shift against the slab bounds, so
  // the test takes the least-squares line through them: its slope is
  // rho0 g and its value at every measured depth rho0 g d, both within 5 %.
  double md = 0, mp = 0;
  for (std::size_t k = 0; k < depths.size(); ++k) {
    md += depths[k] / depths.size();
    mp += pressures[k] / depths.size();
  }
  double sdd = 0, sdp = 0;
  for (std::size_t k = 0; k < depths.size(); ++k) {
    sdd += (depths[k] - md) * (depths[k] - md);
    sdp += (depths[k] - md) * (pressures[k] - mp);
  }
  const double slope = sdp / sdd;
  EXPECT_NEAR(slope / (rho0 * g), 1.0, 0.05);
  double worst_slab = 0;
  for (std::size_t k = 0; k < depths.size(); ++k) {
    const double hydrostatic = rho0 * g * depths[k];
    const double fitted = mp + slope * (depths[k] - md);
    EXPECT_NEAR(fitted / hydrostatic, 1.0, 0.05) << "depth " << depths[k] << " m";
    worst_slab = std::max(worst_slab, std::fabs(pressures[k] / hydrostatic - 1.0));
  }
  ::testing::Test::RecordProperty("worst_slab_deviation", std::to_string(worst_slab));
  ::testing::Test::RecordProperty("pressure_slope_over_rho_g", std::to_string(slope / (rho0 * g)));
}

TEST(Hydrostatics, SettledColumnIsIncompressibleAndPressureIsRhoGDepth) {
  check_settled_column_is_incompressible_and_hydrostatic(false);
}

TEST(Hydrostatics, WarmStartedSettledColumnIsIncompressibleAndPressureIsRhoGDepth) {
  check_settled_column_is_incompressible_and_hydrostatic(true);
}

// DFSPH's pressure p_i is the sum of both solves' kappa_i rho_i.
TEST(Hydrostatics, DfsphSettledColumnIsIncompressibleAndPressureIsRhoGDepth) {
  check_settled_column_is_incompressible_and_hydrostatic(false, PressureSolverMethod::Dfsph);
}

// Liquid at rest stays at rest across a frame that ends just after a whole
// step. Cutting only the last step short leaves a sliver (here 1.6 us after
// 1 ms steps), and PCISPH removes the density error left by the previous
// step within the step it is given: its pressures grow as 1/dt^2 and the
// sliver throws particles off (a drop's rim at 5 m/s in the drop_notex
// scene). advance_to takes equal steps instead.
TEST(Hydrostatics, FrameEndingJustAfterAStepLeavesTheColumnAtRest) {
  SimulationSetup setup = column_in_tank(0.01f, 6, 10, 6).setup;
  setup.time_step.mode = TimeStepMode::Fixed;
  setup.time_step.max_step = 1e-3f;
  auto sim = make_simulation(ExecutionConfig{Device::Cpu, 0}, setup);

  sim->advance_to(0.5);
  const float settled = largest_speed(*sim);
  ASSERT_LT(settled, 0.05f) << "the column has not settled";
  const double frame_end = sim->time() + 10 * 1e-3 + 1.6e-6;
  std::vector<float> steps;
  sim->advance_to(frame_end, [&](const StepReport& r) { steps.push_back(r.dt); });

  EXPECT_NEAR(sim->time(), frame_end, 1e-9);
  ASSERT_EQ(steps.size(), 11u);
  for (float dt : steps) EXPECT_NEAR(dt, (10e-3 + 1.6e-6) / 11, 1e-9);
  // At rest, as hydrostatics has it: no faster than settling left it (a
  // sliver step reached metres per second).
  EXPECT_LT(largest_speed(*sim), std::max(2 * settled, 0.01f));
  RecordProperty("settled_speed", std::to_string(settled));
  RecordProperty("speed_after_frame", std::to_string(largest_speed(*sim)));
}

// A column 60 layers deep, started 1.2 spacings off the walls (scene blocks
// stand 1-2 off), at the CFL step. Left to itself, its settling pushes liquid into
// the gaps along the walls and up the tank's vertical edges at a third of
// Torricelli's sqrt(2 g H) (0.80 of 2.43 m/s here; the glass scene's
// shrinking steps, issue #3). Settled first (SettleSettings), it stays at
// rest from t = 0 on, as hydrostatics has it, within the few centimetres
// per second that PCISPH's density error leaves.
TEST(Hydrostatics, DeepColumnSettledBeforeTheFirstStepStaysAtRest) {
  const float s = 0.005f;
  const int layers = 60;
  SimulationSetup setup = column_in_tank(s, 6, layers, 6).setup;
  setup.liquid.xsph_epsilon = 0.05f;  // the glass scene's
  setup.liquid.boundary_friction = 0.02f;
  setup.settle.duration = 0.5f;
  const double torricelli = std::sqrt(2 * 9.81 * layers * s);

  auto sim = make_simulation(ExecutionConfig{Device::Cpu, 0}, setup);
  sim->settle();
  EXPECT_EQ(sim->time(), 0.0);
  EXPECT_EQ(sim->step_count(), 0);
  EXPECT_EQ(largest_speed(*sim), 0.0f);
  float peak = 0;
  sim->advance_to(0.3, [&](const StepReport&) { peak = std::max(peak, largest_speed(*sim)); });

  RecordProperty("torricelli_speed", std::to_string(torricelli));
  RecordProperty("peak_speed", std::to_string(peak));
  EXPECT_LT(peak, 0.05 * torricelli);
  EXPECT_LT(sim->last_step().density_error, setup.pressure.max_density_error);
}

// The deep column again, settled and then run for 0.2 s, from zero pressure
// each step and warm-started (kWarmStartShare of the last step's): the warm
// solves stay at rest and meet eta as the cold ones do, in at most two
// thirds of their iterations (at this depth about half: each step then
// rebuilds half the hydrostatic pressure instead of all of it).
TEST(Hydrostatics, WarmStartedDeepColumnStaysAtRestInFewerIterations) {
  const float s = 0.005f;
  const int layers = 60;
  const double torricelli = std::sqrt(2 * 9.81 * layers * s);
  double iterations[2] = {0, 0};
  for (bool warm : {false, true}) {
    SimulationSetup setup = column_in_tank(s, 6, layers, 6).setup;
    setup.liquid.xsph_epsilon = 0.05f;
    setup.liquid.boundary_friction = 0.02f;
    setup.settle.duration = 0.5f;
    setup.pressure.warm_start = warm;
    auto sim = make_simulation(ExecutionConfig{Device::Cpu, 0}, setup);
    sim->settle();
    float peak = 0;
    int steps = 0;
    sim->advance_to(0.2, [&](const StepReport& r) {
      peak = std::max(peak, largest_speed(*sim));
      iterations[warm] += r.pressure_iterations;
      ++steps;
      EXPECT_LE(r.density_error, setup.pressure.max_density_error) << (warm ? "warm" : "cold") << " step " << steps;
    });
    iterations[warm] /= steps;
    EXPECT_LT(peak, 0.05 * torricelli) << (warm ? "warm" : "cold");
  }
  RecordProperty("cold_iterations_per_step", std::to_string(iterations[0]));
  RecordProperty("warm_iterations_per_step", std::to_string(iterations[1]));
  EXPECT_LT(iterations[1], 2.0 / 3.0 * iterations[0]);
}

// PCISPH in a deep column needs more iterations the longer the step (43 at
// 2 ms here, 11 at 1 ms). With the cap below what the CFL step needs, the
// step is solved again at half the length and converges there; the steps
// after it lengthen by 5 % each (ConvergedStepLimit) instead of failing at
// full length every time. A fixed step is never shortened.
TEST(Hydrostatics, StepWhosePressureSolveMissesEtaAtTheCapIsHalved) {
  SimulationSetup setup = column_in_tank(0.005f, 6, 60, 6).setup;
  setup.settle.duration = 0.5f;
  auto sim = make_simulation(ExecutionConfig{Device::Cpu, 0}, setup);
  sim->settle();
  const SimulationState settled = sim->state();
  setup.pressure.max_iterations = 8;
  sim = make_simulation(ExecutionConfig{Device::Cpu, 0}, setup);
  sim->restore(settled);

  const StepReport first = sim->step();
  EXPECT_GE(first.pressure_halvings, 1);
  EXPECT_LT(first.dt, 0.5f * setup.time_step.max_step);
  EXPECT_LE(first.density_error, setup.pressure.max_density_error);
  const StepReport second = sim->step();
  EXPECT_LE(second.dt, 1.05f * first.dt * (1 + 1e-6f));

  setup.time_step.mode = TimeStepMode::Fixed;
  auto fixed = make_simulation(ExecutionConfig{Device::Cpu, 0}, setup);
  fixed->restore(settled);
  const StepReport unhalved = fixed->step();
  EXPECT_EQ(unhalved.pressure_halvings, 0);
  EXPECT_EQ(unhalved.dt, setup.time_step.max_step);
  EXPECT_GT(unhalved.density_error, setup.pressure.max_density_error);
}

}  // namespace
}  // namespace dp
