// simulation.domain.leaving: a particle carried past the domain's box stops
// the run (the default) or leaves the shot with its mass in the ledger.
#include <gtest/gtest.h>

#include <cstring>

#include "simulation.h"
#include "test_scenes.h"

namespace dp {
namespace {

// A block slid off its plate at 1 m/s: it runs off the plate's edge (0.12 m)
// and falls out through the domain's floor (y = -0.05 m) and side (0.2 m).
SimulationSetup block_sliding_off_the_plate(DomainLeaving leaving) {
  SimulationSetup setup = test::block_over_plate(6, 4, 6);
  for (Vec3& v : setup.liquid_velocity) v = Vec3{1.0f, 0.0f, 0.0f};
  setup.leaving = leaving;
  return setup;
}

constexpr double kDuration = 0.4;  // s: by then 130 of the 144 particles have left

TEST(DomainLeaving, StopIsAnInstabilityNamingThePosition) {
  auto sim = make_simulation(ExecutionConfig{Device::Cpu, 2}, block_sliding_off_the_plate(DomainLeaving::Stop));
  try {
    sim->advance_to(kDuration);
    FAIL() << "expected InstabilityError";
  } catch (const InstabilityError& e) {
    EXPECT_EQ(e.quantity, "position");
  }
}

TEST(DomainLeaving, RemovedParticlesTakeTheirMassIntoTheLedger) {
  const SimulationSetup setup = block_sliding_off_the_plate(DomainLeaving::Remove);
  auto sim = make_simulation(ExecutionConfig{Device::Cpu, 2}, setup);
  const std::size_t initial = setup.liquid_position.size();
  int reported = 0;
  sim->advance_to(kDuration, [&](const StepReport& r) { reported += r.particles_left_domain; });
  const ParticleSnapshot p = sim->particles();
  const SimulationState s = sim->state();
  // Some left, some stayed (on the plate, or still above the domain's floor).
  EXPECT_GT(s.left_domain_particles, 0u);
  EXPECT_GT(p.size(), 0u);
  EXPECT_EQ(p.size() + s.left_domain_particles, initial);
  EXPECT_EQ(static_cast<std::uint64_t>(reported), s.left_domain_particles);
  EXPECT_EQ(s.left_domain_units, s.left_domain_particles * kFullParticleUnits);
  // The ledger closes with liquid_out (a particle past the box at the last
  // step's end still counts as liquid; it is removed at the next step's start).
  const WaterLedger l = sim->water_ledger();
  EXPECT_GT(l.liquid_out_kg, 0.0);
  EXPECT_NEAR(l.liquid_kg + l.liquid_out_kg, l.initial_kg, 1e-12 * l.initial_kg);
  EXPECT_NEAR(l.drift_kg(), 0.0, 1e-12 * l.initial_kg);
  RecordProperty("left", std::to_string(s.left_domain_particles) + " of " + std::to_string(initial));
}

// Compaction keeps the survivors' order, so removal is as deterministic as
// the rest of a CPU step; and a run restored after removals continues as
// one that was never interrupted.
TEST(DomainLeaving, RemovalIsBitIdenticalForAnyThreadCountAndAcrossARestore) {
  const SimulationSetup setup = block_sliding_off_the_plate(DomainLeaving::Remove);
  auto one = make_simulation(ExecutionConfig{Device::Cpu, 1}, setup);
  auto two = make_simulation(ExecutionConfig{Device::Cpu, 2}, setup);
  // Both stop at the half-way time, as a run writing frames would.
  one->advance_to(kDuration / 2);
  one->advance_to(kDuration);
  two->advance_to(kDuration / 2);
  auto resumed = make_simulation(ExecutionConfig{Device::Cpu, 2}, setup);
  resumed->restore(two->state());
  ASSERT_GT(resumed->state().left_domain_particles, 0u);
  resumed->advance_to(kDuration);
  const ParticleSnapshot a = one->particles(), b = resumed->particles();
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.position.data(), b.position.data(), a.size() * sizeof(Vec3)), 0);
  EXPECT_EQ(one->water_ledger().liquid_out_kg, resumed->water_ledger().liquid_out_kg);
}

}  // namespace
}  // namespace dp
