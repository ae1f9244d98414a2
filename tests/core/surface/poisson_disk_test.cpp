// Particle seeding points (paper Sec. 4.3) by Poisson-disk sampling after
// Bridson 2007, against the definition: no two samples closer than r, and
// maximal, i.e. no point of the surface farther than r from every sample
// (no empty disc wider than 2r, so no room for another sample). Bounds that
// any maximal r-sampling of an area A satisfies are checked as well: discs
// of radius r around the samples cover A (N pi r^2 >= A) and discs of radius
// r/2 are disjoint, so their density is below Thue's hexagonal packing
// density pi / sqrt(12).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "surface/seeding_points.h"
#include "surface_scenes.h"

namespace dp {
namespace {

constexpr float kR = 0.01f;

double nearest(const std::vector<Vec3>& points, Vec3 p) {
  double best = 1e30;
  for (const Vec3& q : points) best = std::min(best, static_cast<double>(length(q - p)));
  return best;
}

void expect_poisson_disk(const std::vector<Vec3>& samples) {
  double closest = 1e30;
  for (std::size_t i = 0; i < samples.size(); ++i)
    for (std::size_t j = i + 1; j < samples.size(); ++j) closest = std::min(closest, static_cast<double>(length(samples[i] - samples[j])));
  EXPECT_GE(closest, kR * (1 - 1e-6));
}

TEST(PoissonDisk, PlaneSamplesKeepTheirDistanceAndLeaveNoGap) {
  const float step = 0.001f, side = 0.2f;
  const TexelGeometry g = test::lattice_texels(201, step, 0.0f);
  const SeedingPoints seeds = make_seeding_points(g, kR);
  ASSERT_GT(seeds.size(), 100u);
  expect_poisson_disk(seeds.position);
  // Maximal at texel resolution: every texel within r of a sample ...
  double farthest_texel = 0;
  for (const Vec3& x : g.position) farthest_texel = std::max(farthest_texel, nearest(seeds.position, x));
  EXPECT_LE(farthest_texel, kR * (1 + 1e-6));  // lengths in float: d < r up to rounding
  // ... and every point of the plate within r plus half a texel diagonal.
  std::mt19937 rng(5);
  double farthest_point = 0;
  for (int i = 0; i < 3000; ++i) {
    const Vec3 p{side * (rng() / 4294967296.0f), 0, side * (rng() / 4294967296.0f)};
    farthest_point = std::max(farthest_point, nearest(seeds.position, p));
  }
  EXPECT_LT(farthest_point, kR + 0.5f * std::sqrt(2.0f) * step);
  const double n = static_cast<double>(seeds.size()), pi = 3.14159265358979;
  const double density = n * pi * kR * kR / 4 / (side * side);
  RecordProperty("disc_density", std::to_string(density));
  EXPECT_GE(n * pi * kR * kR, side * side);                                    // covering
  EXPECT_LE(n * pi * kR * kR / 4, pi / std::sqrt(12.0) * (side + kR) * (side + kR));  // packing
}

// Texels on a sphere (Fibonacci lattice, equal areas): distances are in
// space, and the sampler must wrap around the whole surface.
TEST(PoissonDisk, SphereSamplesKeepTheirDistanceAndCoverIt) {
  TexelGeometry g;
  const int n = 40000;
  const float radius = 0.1f;
  const double golden = 3.14159265358979 * (3 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double y = 1 - 2 * (i + 0.5) / n, r = std::sqrt(1 - y * y), a = golden * i;
    const Vec3 u{static_cast<float>(r * std::cos(a)), static_cast<float>(y), static_cast<float>(r * std::sin(a))};
    g.pixel.push_back(i);
    g.position.push_back(radius * u);
    g.normal.push_back(u);
    g.area.push_back(static_cast<float>(4 * 3.14159265358979 * radius * radius / n));
    g.max_mass.push_back(0);
  }
  g.width = n;
  g.height = 1;
  const SeedingPoints seeds = make_seeding_points(g, kR);
  expect_poisson_disk(seeds.position);
  double farthest = 0;
  for (const Vec3& x : g.position) farthest = std::max(farthest, nearest(seeds.position, x));
  EXPECT_LE(farthest, kR * (1 + 1e-6));
  for (const Vec3& x : seeds.position) EXPECT_NEAR(length(x), radius, 1e-6f);
}

TEST(PoissonDisk, EveryTexelFeedsItsNearestSeed) {
  const TexelGeometry g = test::lattice_texels(81, 0.0025f, 0.0f);
  const SeedingPoints seeds = make_seeding_points(g, kR);
  ASSERT_EQ(seeds.texel_offset.size(), seeds.size() + 1);
  std::vector<int> owners(g.size(), 0);
  for (std::size_t s = 0; s < seeds.size(); ++s)
    for (std::uint32_t k = seeds.texel_offset[s]; k < seeds.texel_offset[s + 1]; ++k) {
      const std::uint32_t t = seeds.texel_index[k];
      ++owners[t];
      const double own = length(g.position[t] - seeds.position[s]);
      EXPECT_LT(own, kR);
      EXPECT_LE(own, nearest(seeds.position, g.position[t]) + 1e-7);
    }
  for (int o : owners) ASSERT_EQ(o, 1);
}

TEST(PoissonDisk, SameTexelsSameSamples) {
  const TexelGeometry g = test::lattice_texels(61, 0.002f, 0.0f);
  const SeedingPoints a = make_seeding_points(g, kR), b = make_seeding_points(g, kR);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(length(a.position[i] - b.position[i]), 0.0f);
}

}  // namespace
}  // namespace dp
