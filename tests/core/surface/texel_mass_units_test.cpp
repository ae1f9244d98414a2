// Texel mass units (surface/texel_mass_units.h): exact conversion to and from
// the liquid's mass units, rounding down of caps, and a clear error where a
// texel mass does not fit in 64 bits.
#include <gtest/gtest.h>

#include <cmath>

#include "surface/texel_mass_units.h"

namespace dp {
namespace {

TEST(TexelMassUnits, AParticleIsAWholeNumberOfTexelUnits) {
  const double particle_mass = 1000.0 * 1e-6;  // 1 cm spacing
  // A full particle: 2^24 liquid units = 2^56 texel units, exactly its mass.
  const TexelMassUnits full = static_cast<TexelMassUnits>(kFullParticleUnits) * kTexelUnitsPerMassUnit;
  EXPECT_EQ(full, TexelMassUnits{1} << 56);
  EXPECT_DOUBLE_EQ(kg_of_texel_units(full, kg_per_texel_unit(particle_mass)), particle_mass);
  // Half a particle in either unit is the same number.
  EXPECT_EQ(static_cast<TexelMassUnits>(kFullParticleUnits / 2) << kTexelUnitShift, full / 2);
}

TEST(TexelMassUnits, KilogramsRoundDownSoCapsAreNeverExceeded) {
  const double particle_mass = 1e-6;
  const double unit = kg_per_texel_unit(particle_mass);
  for (double kg : {1e-14, 3.3e-9, 7.77e-7, 1e-5}) {
    const TexelMassUnits u = texel_units_of_kg(kg, particle_mass);
    EXPECT_LE(kg_of_texel_units(u, unit), kg);
    EXPECT_GT(kg_of_texel_units(u + 1, unit), kg * (1 - 1e-15));
  }
  // A typical per-step condensation onto a 1 mm^2 texel is millions of units.
  EXPECT_GT(texel_units_of_kg(5e-14, particle_mass), 1000000u);
}

TEST(TexelMassUnits, MassBeyondSixtyFourBitsIsAClearError) {
  const double particle_mass = 1e-6;
  EXPECT_NO_THROW(texel_units_of_kg(255 * particle_mass, particle_mass));
  try {
    texel_units_of_kg(300 * particle_mass, particle_mass);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("exceeds what a texel can hold"), std::string::npos) << e.what();
  }
  EXPECT_THROW(texel_units_of_kg(-1.0, particle_mass), std::invalid_argument);
}

TEST(TexelMassUnits, SumsAreExactBeyondSixtyFourBits) {
  // 1000 texels near the 64-bit limit: the total needs more than 64 bits.
  TexelMassSum sum;
  unsigned __int128 reference = 0;
  std::uint64_t x = 88172645463325252ull;
  for (int i = 0; i < 1000; ++i) {
    x ^= x << 13, x ^= x >> 7, x ^= x << 17;  // xorshift64
    sum.add(x);
    reference += x;
  }
  EXPECT_EQ(sum.texel_units, static_cast<std::uint64_t>(reference & (kTexelUnitsPerMassUnit - 1)));
  EXPECT_EQ(sum.mass_units, static_cast<std::uint64_t>(reference >> kTexelUnitShift));
}

}  // namespace
}  // namespace dp
