// Boundary sampling of rigid meshes at the particle spacing.
#include <gtest/gtest.h>

#include "rigid/sample_surface.h"

namespace dp {
namespace {

TEST(SampleSurface, SquareOfTwoTrianglesGivesTheRegularGrid) {
  // A 1 m square split along its diagonal, sampled at 0.1 m: the 11 x 11
  // grid, each point once.
  std::vector<std::array<float, 3>> p = {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}};
  std::vector<std::array<std::uint32_t, 3>> t = {{0, 1, 2}, {0, 2, 3}};
  std::vector<Vec3> s = sample_surface(p, t, 0.1f);
  EXPECT_EQ(s.size(), 121u);
  float closest = 1e9f;
  for (std::size_t i = 0; i < s.size(); ++i)
    for (std::size_t j = i + 1; j < s.size(); ++j) closest = std::min(closest, length(s[i] - s[j]));
  EXPECT_NEAR(closest, 0.1f, 1e-5f);
}

TEST(SampleSurface, NoPointOfTheSurfaceIsFartherThanTheSpacing) {
  std::vector<std::array<float, 3>> p = {{0, 0, 0}, {0.73f, 0.1f, 0}, {0.2f, 0.5f, 0.3f}};
  std::vector<std::array<std::uint32_t, 3>> t = {{0, 1, 2}};
  const float spacing = 0.05f;
  std::vector<Vec3> s = sample_surface(p, t, spacing);
  Vec3 a{0, 0, 0}, b{0.73f, 0.1f, 0}, c{0.2f, 0.5f, 0.3f};
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; i + j <= 40; ++j) {
      Vec3 x = a + (i / 40.0f) * (b - a) + (j / 40.0f) * (c - a);
      float nearest = 1e9f;
      for (const Vec3& q : s) nearest = std::min(nearest, length(x - q));
      EXPECT_LE(nearest, spacing) << i << "," << j;
    }
}

}  // namespace
}  // namespace dp
