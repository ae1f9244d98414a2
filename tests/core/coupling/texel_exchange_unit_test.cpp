// Alg. 2's invariants (paper Sec. 6.2) over random masses, rates and caps,
// the trilinear stencil, the wetting rule, thread-count independence and
// the exact scaling of transfers.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "coupling/exact_units.h"
#include "texel_box.h"

namespace dp {
namespace {

TEST(coupling_Stencil, WeightsSumToOneAndReproduceLinearFields) {
  const MacGrid g = mac_grid_covering(Vec3{0, 0, 0}, Vec3{0.1f, 0.05f, 0.08f}, 10);
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int n = 0; n < 200; ++n) {
    const Vec3 p{0.006f + 0.088f * u(rng), 0.006f + 0.038f * u(rng), 0.006f + 0.068f * u(rng)};
    std::uint32_t cell[kStencilSize];
    float alpha[kStencilSize];
    trilinear_stencil(g, p, cell, alpha);
    double sum = 0;
    Vec3 x{0, 0, 0};
    for (int k = 0; k < kStencilSize; ++k) {
      int i, j, l;
      g.cell_coords(cell[k], i, j, l);
      sum += alpha[k];
      x = x + alpha[k] * g.cell_center(i, j, l);
    }
    EXPECT_NEAR(sum, 1.0, 1e-6);
    EXPECT_NEAR(length(x - p), 0.0, 1e-6);  // interior points: trilinear is exact for x itself
  }
}

// A thin plate (one layer of rigid particles) in the plane y = y0, its
// texels on both faces with normals +y and -y. The cells holding the
// plate's particles are solid and drop out of the exchange (air_weights);
// every other cell of a texel's stencil must lie on the texel's own side of
// the plate, and some must be left, wherever the plate lies in its cell: on
// a face, a quarter, half or three quarters up.
TEST(coupling_Stencil, TexelsExchangeWithTheAirOnTheirOwnSideOfAThinPlate) {
  const MacGrid g = mac_grid_covering(Vec3{0, 0, 0}, Vec3{0.2f, 0.2f, 0.2f}, 8);  // dx = 2.5 cm
  for (float fraction : {0.0f, 0.25f, 0.5f, 0.75f}) {
    const float y0 = g.origin.y + (3 + fraction) * g.dx;
    int plate_layer, i_unused, k_unused;
    g.cell_coords(static_cast<std::uint32_t>(g.cell(0, static_cast<int>(std::floor((y0 - g.origin.y) / g.dx)), 0)), i_unused, plate_layer,
                  k_unused);
    for (float side : {1.0f, -1.0f}) {
      const Vec3 position{0.1f, y0, 0.1f}, normal{0, side, 0};
      std::uint32_t cell[kStencilSize];
      float alpha[kStencilSize];
      ComputeStencilsInFront{g, &position, &normal, cell, alpha, 1}(0);  // one texel: corner-major is contiguous
      float air = 0.0f;
      for (int k = 0; k < kStencilSize; ++k) {
        int i, j, l;
        g.cell_coords(cell[k], i, j, l);
        if (alpha[k] == 0.0f || j == plate_layer) continue;
        air += alpha[k];
        EXPECT_GT(side * (g.cell_center(i, j, l).y - y0), 0.0f) << "plate at " << fraction << " of a cell, side " << side;
      }
      EXPECT_GT(air, 0.25f) << "plate at " << fraction << " of a cell, side " << side;
    }
  }
}

// Random texels (temperatures 0..60 degC, masses, caps including 0,
// wetting) in air of random humidity, with steps long enough that every
// bound of Alg. 2 binds somewhere.
test::TexelBox random_box(int threads, unsigned seed) {
  AirSettings s = test::quiet_air_box(6, 0.06f);
  test::TexelBox b(threads, s);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int n = 0; n < 400; ++n) {
    const double cap = u(rng) < 0.2 ? 0.0 : 1e-9 * u(rng);
    b.add_lattice(1, 0.003f, 0.003f + 0.054f * static_cast<float>(u(rng)), 0.003f + 0.054f * static_cast<float>(u(rng)),
                  0.003f + 0.054f * static_cast<float>(u(rng)), static_cast<float>(273.15 + 60 * u(rng)), cap * u(rng), cap);
    b.wetting.back() = u(rng) < 0.2 ? 1.0f : 0.0f;
  }
  b.prepare();
  AirSnapshot a = b.air.snapshot();
  for (double& rho : a.vapor) rho = u(rng) < 0.3 ? 0.0 : 0.03 * u(rng);
  b.air.set_vapor(b.exec, a.vapor);
  return b;
}

// floor(x num / den) by shift and subtract over the 128-bit product's bits:
// a reference independent of both the compiler's 128-bit division and the
// CPU's divq, which scale_units uses on x86-64.
std::uint64_t floor_of_scaled_by_bits(std::uint64_t x, std::uint64_t num, std::uint64_t den) {
  __extension__ typedef unsigned __int128 Wide;
  const Wide product = static_cast<Wide>(x) * num;
  Wide remainder = 0, quotient = 0;
  for (int bit = 127; bit >= 0; --bit) {
    remainder = (remainder << 1) | ((product >> bit) & 1);
    quotient <<= 1;
    if (remainder >= den) {
      remainder -= den;
      quotient |= 1;
    }
  }
  return static_cast<std::uint64_t>(quotient);
}

// w_t and w_c scale a transfer to floor(x num / den), num < den; at or
// above 1 (and for den 0) the transfer stays as it is. UnitScale, the cells'
// way for many x, gives the same units.
TEST(coupling_ExactUnits, ScaledUnitsAreTheFloorOfTheExactQuotient) {
  const std::uint64_t top = static_cast<std::uint64_t>(kMaxTransferUnits);
  std::mt19937_64 rng(3);
  std::vector<std::uint64_t> values{0, 1, 2, 3, 255, 256, (1ull << 32) - 1, 1ull << 32, top - 1, top};
  for (int n = 0; n < 20; ++n) values.push_back(rng() % top);
  for (int n = 0; n < 20; ++n) values.push_back(rng() % 4096);
  // Around 2^51, where UnitScale stops estimating, and quotients near whole numbers.
  for (std::uint64_t v : {(1ull << 51) - 1, 1ull << 51, (1ull << 51) + 1, (1ull << 53) + 1, 3ull << 50}) values.push_back(v);
  for (int n = 0; n < 10; ++n) values.push_back((rng() % (1ull << 40)) * 3);
  int checked = 0;
  for (std::uint64_t x : values)
    for (std::uint64_t num : values)
      for (std::uint64_t den : values) {
        const UnitScale scale(num, den);
        if (den == 0 || num >= den) {
          ASSERT_EQ(scale_units(x, num, den), x);
          ASSERT_EQ(scale(x), x);
          continue;
        }
        const std::uint64_t floor = floor_of_scaled_by_bits(x, num, den);
        ASSERT_EQ(scale_units(x, num, den), floor) << x << " * " << num << " / " << den;
        ASSERT_EQ(scale(x), floor) << "UnitScale: " << x << " * " << num << " / " << den;
        ++checked;
      }
  EXPECT_GT(checked, 50000);
}

TEST(coupling_Alg2, RandomStatesKeepEveryBoundAndConserveExactly) {
  test::TexelBox b = random_box(1, 7);
  const test::WideUnits water0 = test::water_units(b);
  const double vapor0 = b.air.vapor_mass(b.exec);
  int capped = 0, emptied = 0;
  for (int step = 0; step < 40; ++step) {
    b.exchange_step(0.5f);
    for (std::size_t t = 0; t < b.mass.size(); ++t) {
      ASSERT_LE(b.mass[t], b.max_mass[t]) << "texel " << t << " above m_t^max (or wrapped below 0) at step " << step;
      // Each of a texel's eight scaled transfers is rounded down, so a bound
      // is reached to within kStencilSize units (1e-19 kg).
      capped += b.max_mass[t] > 0 && b.mass[t] + kStencilSize >= b.max_mass[t];
      emptied += b.max_mass[t] > 0 && b.mass[t] <= kStencilSize;
    }
    const AirSnapshot a = b.air.snapshot();
    for (std::size_t c = 0; c < a.vapor.size(); ++c) ASSERT_GE(a.vapor[c], -1e-18) << "cell " << c << " at step " << step;
    ASSERT_TRUE(test::water_units(b) == water0) << "units not conserved at step " << step;
  }
  EXPECT_GT(capped, 0);
  EXPECT_GT(emptied, 0);
  // The double-valued air holds what it was credited with, to rounding.
  const double moved = static_cast<double>(b.air_units) * b.params.kg_per_unit;
  EXPECT_NEAR(b.air.vapor_mass(b.exec) - vapor0, moved, 1e-12 * vapor0);
}

TEST(coupling_Alg2, IndependentOfThreadCount) {
  test::TexelBox one = random_box(1, 11), two = random_box(2, 11);
  for (int step = 0; step < 3; ++step) {
    one.step(0.05f);
    two.step(0.05f);
  }
  EXPECT_EQ(one.mass, two.mass);
  EXPECT_EQ(one.air.snapshot().vapor, two.air.snapshot().vapor);
}

TEST(coupling_Alg2, RecentlyWettedTexelsDoNotCondense) {
  AirSettings s = test::quiet_air_box(4, 0.04f);
  s.ambient_vapor = vapor_density_at_humidity(0.9, 293.15);
  test::TexelBox b(1, s);
  b.add_lattice(2, 0.004f, 0.02f, 0.016f, 0.016f, 277.15f, 0, 1e-8);
  b.wetting[0] = 1.0f;
  b.wetting[1] = 0.5f;
  b.wetting[2] = 0.3f;  // wetted more than one decay time ago
  b.prepare();
  b.exchange_step(0.1f);
  EXPECT_EQ(b.mass[0], 0u);
  EXPECT_EQ(b.mass[1], 0u);
  EXPECT_GT(b.mass[2], 0u);
  EXPECT_GT(b.mass[3], 0u);
}

}  // namespace
}  // namespace dp
