// A particle that evaporates completely: its units reach 0 exactly and all
// of them are in the air; a weight-0 particle is then removed by the
// adaptivity step (MarkLive, tested in tests/core/adaptivity).
#include <gtest/gtest.h>

#include "coupling/particle_evaporation.h"
#include "texel_box.h"

namespace dp {
namespace {

TEST(coupling_ParticleEvaporation, ASpentParticleGivesTheAirExactlyWhatItHad) {
  CpuExec exec(1);
  AirSettings s = test::quiet_air_box(4, 0.2f);
  test::SortedParticles none(exec, {}, s.domain_min, s.domain_max, 0.1f);
  AirGrid<CpuExec> air(exec, s, Vec3{0, -9.81f, 0}, none.view());
  std::vector<Vec3> position{Vec3{0.07f, 0.08f, 0.11f}, Vec3{0.12f, 0.12f, 0.12f}};
  std::vector<float> area{1e-4f, 1e-4f}, temperature{363.15f, 283.15f};
  std::vector<std::uint32_t> id{4, 9}, cell(16);
  std::vector<float> alpha(16);
  std::vector<MassUnits> units{10, kFullParticleUnits};
  std::vector<TexelMassUnits> eva(16);
  exec.parallel_for(2, ComputeStencils{air.grid(), position.data(), cell.data(), alpha.data()});
  EvaporationCoefficients k;
  const double unit = kg_per_texel_unit(test::kTestParticleMass);
  std::vector<Vec3> still(air.grid().cell_count(), Vec3{0, 0, 0});
  exec.parallel_for(2, EvaporateParticles{air.view(), still.data(), cell.data(), alpha.data(), area.data(), temperature.data(),
                                          id.data(), k, 0.01f, unit, 0, units.data(), eva.data(), 0.0f});
  EXPECT_EQ(units[0], 0u);  // 10 units (6e-10 kg) against 8.7e-10 kg of Eq. 16 at 90 degC
  TexelMassUnits given = 0;
  for (int p = 0; p < 8; ++p) given += eva[p];
  EXPECT_EQ(given, TexelMassUnits{10} << kTexelUnitShift);
  // The full 10 degC particle loses Eq. 16's amount on average, in whole units.
  const AirAtSurfel dry{0, 293.15, 0};
  const double expected = evaporation_rate(1e-4, k, 283.15, dry) * 0.01 / (unit * kTexelUnitsPerMassUnit);
  const double lost = kFullParticleUnits - units[1];
  EXPECT_LE(std::fabs(lost - expected), 1.0);
  TexelMassUnits second = 0;
  for (int p = 8; p < 16; ++p) second += eva[p];
  EXPECT_EQ(second, static_cast<TexelMassUnits>(lost) << kTexelUnitShift);
}

TEST(coupling_ParticleEvaporation, LatentHeatCoolsByLTimesLostMassOverHeatCapacity) {
  CpuExec exec(1);
  AirSettings s = test::quiet_air_box(4, 0.2f);
  test::SortedParticles none(exec, {}, s.domain_min, s.domain_max, 0.1f);
  AirGrid<CpuExec> air(exec, s, Vec3{0, -9.81f, 0}, none.view());
  std::vector<Vec3> position{Vec3{0.07f, 0.08f, 0.11f}}, still(air.grid().cell_count(), Vec3{0, 0, 0});
  std::vector<float> area{1e-4f}, temperature{363.15f};
  std::vector<std::uint32_t> id{4}, cell(8);
  std::vector<float> alpha(8);
  std::vector<MassUnits> units{kFullParticleUnits};
  std::vector<TexelMassUnits> eva(8);
  exec.parallel_for(1, ComputeStencils{air.grid(), position.data(), cell.data(), alpha.data()});
  const float L = 2.26e6f, C = 4186.0f;
  exec.parallel_for(1, EvaporateParticles{air.view(), still.data(), cell.data(), alpha.data(), area.data(), temperature.data(), id.data(),
                                          EvaporationCoefficients{}, 0.01f, kg_per_texel_unit(test::kTestParticleMass), 0,
                                          units.data(), eva.data(), L / C});
  const double lost = static_cast<double>(kFullParticleUnits - units[0]) / kFullParticleUnits;  // of the particle's mass
  ASSERT_GT(lost, 0);
  // Energy balance: L dm = m_after C dT.
  EXPECT_NEAR(363.15 - temperature[0], L * lost / ((1 - lost) * C), 1e-4);
}

TEST(coupling_StochasticRounding, KeepsTheExpectedValue) {
  // Adding 1e-6 K to 300 K (ulp 3e-5 K) 100000 times: nearest rounding
  // never moves; stochastic rounding moves by 0.1 K on average.
  float t = 300.0f;
  for (std::uint32_t s = 0; s < 100000; ++s) t = stochastic_round_to_float(static_cast<double>(t) + 1e-6, rounding_hash(7, s));
  EXPECT_NEAR(t, 300.1, 0.01);
}

}  // namespace
}  // namespace dp
