// Phase 3 in the whole step: heat between particles and air, particle
// evaporation into the air with the water ledger, thread-count independence.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>

#include "backend/cpu_isa.h"
#include "coupled_scenes.h"

namespace dp {
namespace {

double particle_heat(const ParticleSnapshot& p, const SimulationSetup& s) {
  double h = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    h += static_cast<double>(p.weight[i]) * s.particle_mass() * s.liquid.specific_heat * p.temperature[i];
  return h;
}
double air_heat(const AirSnapshot& a, const CouplingSettings& c) {
  double h = 0;
  for (float t : a.temperature) h += t;
  return h * c.air.density * c.air.specific_heat * a.grid.cell_volume();
}

TEST(coupling_HeatGridParticles, HotBlockInColdAirConservesHeat) {
  SimulationSetup s = test::liquid_cube_in_air(4, 353.15f, 0.0);
  s.coupling.particle_evaporation = false;
  auto sim = make_simulation(ExecutionConfig{Device::Cpu, 1}, s);
  const double p0 = particle_heat(sim->particles(), s), a0 = air_heat(*sim->air(), s.coupling);
  for (int step = 0; step < 100; ++step) sim->step();
  const double p1 = particle_heat(sim->particles(), s), a1 = air_heat(*sim->air(), s.coupling);
  const double moved = p0 - p1, drift = (p1 + a1) - (p0 + a0);
  char line[160];
  std::snprintf(line, sizeof line, "moved %.3e J, drift %.3e J (%.2e of the total, %.2e of the moved)", moved, drift,
                drift / (p0 + a0), drift / moved);
  RecordProperty("heat", line);
  EXPECT_GT(moved, 0) << "the hot block must warm the air";
  EXPECT_GT(a1 - a0, 0);
  EXPECT_LT(std::fabs(drift) / (p0 + a0), 1e-6) << line;
}

TEST(coupling_ParticleEvaporation, HotDropLosesMassToTheAirAndTheLedgerCloses) {
  // Paper Fig. 6 in small: water near boiling in dry air, the rate
  // coefficient raised 1000x (the air around saturates after a few % of
  // the drop; complete evaporation of one particle is particle_evaporation_test).
  SimulationSetup s = test::liquid_cube_in_air(3, 368.15f, 0.0);
  s.coupling.heat_exchange = false;
  s.heat_conduction = false;
  s.coupling.coefficients.a *= 1000;
  auto sim = make_simulation(ExecutionConfig{Device::Cpu, 1}, s);
  const WaterLedger l0 = sim->water_ledger();
  double last_liquid = l0.liquid_kg, worst = 0;
  for (int step = 0; step < 150; ++step) {
    sim->step();
    const WaterLedger l = sim->water_ledger();
    ASSERT_LE(l.liquid_kg, last_liquid) << "liquid mass must not grow, step " << step;
    last_liquid = l.liquid_kg;
    worst = std::fmax(worst, std::fabs(l.relative_drift()));
    EXPECT_NEAR(l.vapor_kg, l0.liquid_kg - l.liquid_kg, 1e-9 * l0.total_kg());
    EXPECT_DOUBLE_EQ(l.liquid_to_air_kg, l0.liquid_kg - l.liquid_kg);
  }
  RecordProperty("worst_relative_drift", std::to_string(worst));
  EXPECT_LT(worst, 1e-9);
  EXPECT_LT(last_liquid, 0.99 * l0.liquid_kg);
}

TEST(coupling_Simulation, IndependentOfThreadCount) {
  SimulationSetup s = test::liquid_cube_in_air(3, 353.15f, 0.0);
  s.coupling.coefficients.a *= 1000;
  auto one = make_simulation(ExecutionConfig{Device::Cpu, 1}, s), two = make_simulation(ExecutionConfig{Device::Cpu, 2}, s);
  for (int step = 0; step < 5; ++step) {
    one->step();
    two->step();
  }
  const ParticleSnapshot a = one->particles(), b = two->particles();
  EXPECT_EQ(a.mass_units, b.mass_units);
  EXPECT_EQ(a.temperature, b.temperature);
  EXPECT_EQ(one->air()->vapor, two->air()->vapor);
  EXPECT_EQ(one->air()->temperature, two->air()->temperature);
}

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

// The CPU launcher's loops in their baseline and AVX2 copies (cpu_isa.h):
// SPH, the air step and the exchanges between them, the same bits.
TEST(coupling_Simulation, SameBitsInTheBaselineAndAvx2Copies) {
  if (!cpu_runs_avx2_copy()) GTEST_SKIP() << "this CPU or build has no AVX2 copy";
  SimulationSetup s = test::liquid_cube_in_air(3, 353.15f, 0.0);
  s.coupling.coefficients.a *= 1000;
  auto baseline = make_simulation(ExecutionConfig{Device::Cpu, 2, CpuIsa::Baseline}, s);
  auto avx2 = make_simulation(ExecutionConfig{Device::Cpu, 2, CpuIsa::Avx2}, s);
  for (int step = 0; step < 5; ++step) {
    baseline->step();
    avx2->step();
  }
  const ParticleSnapshot a = baseline->particles(), b = avx2->particles();
  EXPECT_TRUE(same_bits(a.position, b.position));
  EXPECT_TRUE(same_bits(a.velocity, b.velocity));
  EXPECT_TRUE(same_bits(a.density, b.density));
  EXPECT_TRUE(same_bits(a.temperature, b.temperature));
  EXPECT_EQ(a.mass_units, b.mass_units);
  const auto air_a = baseline->air(), air_b = avx2->air();
  EXPECT_TRUE(same_bits(air_a->vapor, air_b->vapor));
  EXPECT_TRUE(same_bits(air_a->temperature, air_b->temperature));
  EXPECT_TRUE(same_bits(air_a->u, air_b->u));
}

}  // namespace
}  // namespace dp
