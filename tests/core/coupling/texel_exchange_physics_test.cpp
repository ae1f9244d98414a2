// Texels <-> air (Alg. 2) against Eq. 12 and the water balance: a warm wet
// texture dries into dry air, a cold texture in humid air fogs only where
// m_t^max allows, and no water is made or lost on the way.
#include <gtest/gtest.h>

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

TEST(coupling_Alg2Physics, DewPointDecidesWhetherAPlateCondenses) {
  // Still air at 20 degC and 60 % RH: T_dew = 12.0 degC (Eq. 11 inverted).
  const double g = std::log(0.6) + 17.62 * 20 / (243.12 + 20), dew = 243.12 * g / (17.62 - g) + kCelsiusZero;
  for (double offset : {-0.3, 0.3}) {
    AirSettings s = still_box();
    s.ambient_vapor = vapor_density_at_humidity(0.6, 293.15);
    test::TexelBox b(1, s);
    b.add_lattice(4, 0.004f, 0.04f, 0.03f, 0.03f, static_cast<float>(dew + offset), 0, 1e-8);
    b.prepare();
    for (int step = 0; step < 20; ++step) b.step(0.01f);
    if (offset < 0) EXPECT_GT(b.texel_kg(), 0) << "no condensation 0.3 K below the dew point";
    else EXPECT_EQ(b.texel_kg(), 0) << "condensation 0.3 K above the dew point";
  }
}

}  // namespace
}  // namespace dp
