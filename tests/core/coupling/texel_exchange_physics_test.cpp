// Texels <-> air (Alg. 2) against Eq. 12 and the water balance: a warm wet
// texture dries into dry air, a cold texture in humid air fogs only where
// m_t^max allows, and no water is made or lost on the way.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "texel_box.h"

namespace dp {
namespace {

AirSettings still_box() {
  AirSettings s = test::quiet_air_box(8, 0.08f);
  s.vapor_diffusivity = 2.5e-5f;
  return s;
}

TEST(coupling_Alg2Physics, FirstStepLossIsAreaTimesATimesSaturationPressure) {
  // Dry still air: p_c = 0 and v = 0, so Eq. 12 is A a p_sat(T_s).
  test::TexelBox b(1, still_box());
  const float T = 313.15f;
  b.add_lattice(10, 0.004f, 0.04f, 0.02f, 0.02f, T, 1e-6, 1e-6);
  b.prepare();
  const double before = b.texel_kg();
  const float dt = 0.01f;
  b.exchange_step(dt);
  const double lost = before - b.texel_kg();
  double area = 0;
  for (float a : b.area) area += a;
  const double expected = area * b.params.coefficients.a * saturation_pressure_at_kelvin(T) * dt;
  RecordProperty("relative_error", std::to_string(lost / expected - 1));
  EXPECT_NEAR(lost, expected, 0.01 * expected);
}

TEST(coupling_Alg2Physics, WetWarmTextureDriesIntoDryAirConservingWater) {
  test::TexelBox b(1, still_box());
  b.add_lattice(10, 0.004f, 0.04f, 0.02f, 0.02f, 313.15f, 1.2e-10, 1e-6);
  b.prepare();
  const test::WideUnits water0 = test::water_units(b);
  const double texels0 = b.texel_kg(), vapor0 = b.air.vapor_mass(b.exec);
  double worst = 0;
  for (int step = 0; step < 300; ++step) {
    b.step(0.01f);
    ASSERT_TRUE(test::water_units(b) == water0) << "step " << step;
    const double total = b.texel_kg() + b.air.vapor_mass(b.exec);
    worst = std::fmax(worst, std::fabs(total - (texels0 + vapor0)) / (texels0 + vapor0));
  }
  RecordProperty("worst_relative_drift", test::sci(worst));
  EXPECT_LT(worst, 1e-9);
  EXPECT_LT(b.texel_kg(), 0.01 * texels0);  // the water is in the air now
  EXPECT_NEAR(b.air.vapor_mass(b.exec) - vapor0, texels0 - b.texel_kg(), 1e-9 * texels0);
}

TEST(coupling_Alg2Physics, ColdMirrorFogsOnlyWhereMaxMassAllows) {
  // Paper Fig. 5: humid 20 degC air, a 4 degC mirror impregnated with a
  // pattern (m_t^max = 0 outside it).
  AirSettings s = still_box();
  s.ambient_vapor = vapor_density_at_humidity(0.8, 293.15);
  test::TexelBox b(1, s);
  b.add_lattice(10, 0.004f, 0.04f, 0.02f, 0.02f, 277.15f, 0, 1e-8);
  for (std::size_t t = 0; t < b.mass.size(); t += 2) b.max_mass[t] = 0;
  b.prepare();
  const double vapor0 = b.air.vapor_mass(b.exec);
  const test::WideUnits water0 = test::water_units(b);
  for (int step = 0; step < 100; ++step) b.step(0.01f);
  for (std::size_t t = 0; t < b.mass.size(); ++t) {
    if (b.max_mass[t] == 0) EXPECT_EQ(b.mass[t], 0u) << t;
    else EXPECT_GT(b.mass[t], 0u) << t;
  }
  EXPECT_TRUE(test::water_units(b) == water0);
  const double gained = b.texel_kg();
  EXPECT_GT(gained, 0);
  EXPECT_NEAR(vapor0 - b.air.vapor_mass(b.exec), gained, 1e-9 * vapor0);
}

// A cold wet plate far below the dew point, with the rate sped up 10^4
// times so that one step's Eq. 17 would take several times the vapor its
// cells hold: condensation must stop where the rate law says it stops, at
// the plate's saturation pressure (Magnus at 4 degC, Eq. 10 at the air's
// 20 degC), and the plate, below the dew point, must never evaporate.
// Alg. 2's floor at m_c >= 0 alone empties the cells, and the wet plate
// then evaporates into them on the next step.
TEST(coupling_Alg2Physics, FastCondensationStopsAtThePlatesSaturationAndNeverEvaporates) {
  AirSettings s = still_box();
  s.ambient_vapor = vapor_density_at_humidity(0.8, 293.15);  // dew point 16.4 degC
  test::TexelBox b(1, s);
  const float plate = 277.15f;
  b.add_lattice(10, 0.004f, 0.04f, 0.02f, 0.02f, plate, 2e-9, 1e-6);
  b.params.coefficients.a *= 1e4;
  b.params.coefficients.b *= 1e4;
  b.prepare();
  const double saturated = vapor_density_at_pressure(saturation_pressure_at_kelvin(plate), 293.15);
  const double demand = b.params.coefficients.a * 0.004 * 0.004 *
                        (vapor_pressure(s.ambient_vapor, 293.15) - saturation_pressure_at_kelvin(plate)) * 0.01;
  const double cell_excess = (s.ambient_vapor - saturated) * std::pow(0.01, 3);
  ASSERT_GT(demand * 8, 4 * cell_excess) << "the test needs a rate that outruns the cells";
  const test::WideUnits water0 = test::water_units(b);
  double lowest = s.ambient_vapor;
  for (int step = 0; step < 40; ++step) {
    const std::vector<TexelMassUnits> before = b.mass;
    b.step(0.01f);
    for (std::size_t t = 0; t < b.mass.size(); ++t)
      ASSERT_GE(b.mass[t], before[t]) << "texel " << t << " evaporated at step " << step;
    const AirSnapshot a = b.air.snapshot();
    for (std::size_t c = 0; c < a.vapor.size(); ++c)
      if (a.kind[c] == kAirCell) lowest = std::fmin(lowest, a.vapor[c]);
  }
  RecordProperty("lowest_over_saturated", std::to_string(lowest / saturated));
  EXPECT_GE(lowest, saturated * (1 - 1e-9));     // never past equilibrium
  EXPECT_LT(lowest, saturated * 1.02);           // and the cells in front reach it
  EXPECT_GT(b.texel_kg(), 100 * 2e-9);           // the plate gained water
  EXPECT_TRUE(test::water_units(b) == water0);
}

// The same fast condensation onto a plate in stripes from 1 to 8.2 degC:
// a cell that texels of several temperatures condense into stops at the
// saturation of the warmest of them (the colder ones alone could take it
// lower), and no cell goes below it. Only Alg. 2 runs, so each cell holds
// what its own texels left it.
TEST(coupling_Alg2Physics, EachCellStopsAtItsWarmestCondensingTexelsSaturation) {
  AirSettings s = still_box();
  s.ambient_vapor = vapor_density_at_humidity(0.8, 293.15);  // dew point 16.4 degC
  test::TexelBox b(2, s);
  b.add_lattice(10, 0.004f, 0.04f, 0.02f, 0.02f, 0.0f, 2e-9, 1e-6);
  for (std::size_t t = 0; t < b.temperature.size(); ++t) b.temperature[t] = 274.15f + 0.8f * static_cast<float>(t % 10);
  b.params.coefficients.a *= 1e4;
  b.params.coefficients.b *= 1e4;
  b.prepare();
  const MacGrid& g = b.air.grid();
  std::vector<float> warmest(g.cell_count(), 0.0f);  // K; 0: no texel's stencil holds the cell
  for (std::size_t t = 0; t < b.position.size(); ++t) {
    std::uint32_t cell[kStencilSize];
    float alpha[kStencilSize];
    trilinear_stencil(g, b.position[t], cell, alpha);
    for (int k = 0; k < kStencilSize; ++k)
      if (alpha[k] > 0) warmest[cell[k]] = std::fmax(warmest[cell[k]], b.temperature[t]);
  }
  const test::WideUnits water0 = test::water_units(b);
  double lowest = 1e9;  // of a cell's vapor over its warmest texel's saturation
  int cells = 0;
  for (int step = 0; step < 40; ++step) {
    b.exchange_step(0.01f);
    const AirSnapshot a = b.air.snapshot();
    cells = 0;
    for (std::size_t c = 0; c < a.vapor.size(); ++c) {
      if (warmest[c] == 0 || a.kind[c] != kAirCell) continue;
      const double saturated = vapor_density_at_pressure(saturation_pressure_at_kelvin(warmest[c]), a.temperature[c]);
      ASSERT_GE(a.vapor[c], saturated * (1 - 1e-6)) << "cell " << c << " below its warmest texel's saturation at step " << step;
      lowest = std::fmin(lowest, a.vapor[c] / saturated);
      ++cells;
    }
  }
  RecordProperty("lowest_over_saturated", std::to_string(lowest));
  EXPECT_GE(cells, 8);
  EXPECT_LT(lowest, 1.02);  // the cells reach it
  EXPECT_TRUE(test::water_units(b) == water0);
}

struct AirState {
  const char* name;
  double celsius, humidity;
  double table_dew_celsius;  // psychrometric tables (e.g. the CRC Handbook's), to 0.1 K
};

// Magnus (Eq. 11) inverted: the temperature at which air of this vapor
// pressure saturates.
double magnus_dew_point_kelvin(double celsius, double humidity) {
  const double g = std::log(humidity) + 17.62 * celsius / (243.12 + celsius);
  return 243.12 * g / (17.62 - g) + kCelsiusZero;
}

// A plate held 0.3 K below the dew point of still air gains water, dry or
// wet; held 0.3 K above it, a dry plate stays dry and a wet one loses water:
// Eq. 12 changes sign exactly at the dew point. Two air states: a room
// (20 degC, 60 %: T_dew 12.0 degC) and saturated warm air (35 degC, 100 %:
// T_dew is the air's own temperature).
TEST(coupling_Alg2Physics, DewPointDecidesBetweenCondensingAndEvaporating) {
  for (const AirState& air : {AirState{"room", 20, 0.6, 12.0}, AirState{"saturated", 35, 1.0, 35.0}}) {
    const double dew = magnus_dew_point_kelvin(air.celsius, air.humidity);
    EXPECT_NEAR(dew - kCelsiusZero, air.table_dew_celsius, 0.1) << air.name;
    for (double held_kg : {0.0, 2e-9})
      for (double offset : {-0.3, 0.3}) {
        AirSettings s = still_box();
        s.ambient_temperature = static_cast<float>(air.celsius + kCelsiusZero);
        s.ambient_vapor = vapor_density_at_humidity(air.humidity, s.ambient_temperature);
        test::TexelBox b(1, s);
        b.add_lattice(4, 0.004f, 0.04f, 0.03f, 0.03f, static_cast<float>(dew + offset), held_kg, 1e-8);
        b.prepare();
        const double before = b.texel_kg();
        for (int step = 0; step < 20; ++step) b.step(0.01f);
        const std::string where = std::string(air.name) + (held_kg > 0 ? ", wet" : ", dry") + " plate " +
                                  (offset < 0 ? "below" : "above") + " the dew point";
        if (offset < 0)
          EXPECT_GT(b.texel_kg(), before) << where;
        else if (held_kg == 0)
          EXPECT_EQ(b.texel_kg(), 0) << where;
        else
          EXPECT_LT(b.texel_kg(), before) << where;
      }
  }
}

}  // namespace
}  // namespace dp
