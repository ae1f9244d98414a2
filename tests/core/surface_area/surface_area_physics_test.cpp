// Particle surface areas (paper Sec. 4.1, after Orthmann et al. 2013)
// against the geometry of lattice bodies: the sum over a body's particles
// is its surface area, interior particles have none, and a wall hides the
// face lying on it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "area_scene.h"

namespace dp {
namespace {

using area_test::lattice_ball;
using area_test::lattice_block;
using area_test::surface_areas;

constexpr float kSpacing = 0.01f;
constexpr double kPi = 3.14159265358979323846;

TEST(surface_area_Geometry, BallSumsToSphereArea) {
  for (int n : {8, 12, 16}) {
    const double r = n * kSpacing;
    const double ratio = surface_areas(lattice_ball(n, kSpacing), {}, kSpacing).total / (4.0 * kPi * r * r);
    std::printf("ball R = %2d spacings: sum A_i / (4 pi R^2) = %.4f\n", n, ratio);
    RecordProperty("ball_ratio_R" + std::to_string(n), std::to_string(ratio));
    EXPECT_NEAR(ratio, 1.0, 0.10) << "R = " << n << " spacings";
  }
}

// Along edges the two faces' colour gradients add as vectors, so |n| is
// sqrt 2 rather than 2 face values: the edges' share of the area is
// under-counted, a deficit that shrinks as 1/L.
TEST(surface_area_Geometry, CubeSumsToSixFaces) {
  for (int n : {16, 24, 32}) {
    const double l = n * kSpacing;
    const double ratio =
        surface_areas(lattice_block(Vec3{}, n, n, n, kSpacing), {}, kSpacing).total / (6.0 * l * l);
    std::printf("cube L = %2d spacings: sum A_i / (6 L^2) = %.4f\n", n, ratio);
    RecordProperty("cube_ratio_L" + std::to_string(n), std::to_string(ratio));
    EXPECT_NEAR(ratio, 1.0, 0.10) << "L = " << n << " spacings";
  }
}

TEST(surface_area_Geometry, InteriorParticlesHaveNoArea) {
  const int n = 12;
  const float h = 2.0f * kSpacing, r = n * kSpacing;
  std::vector<Vec3> ball = lattice_ball(n, kSpacing);
  area_test::Areas a = surface_areas(ball, {}, kSpacing);
  double outer_sum = 0, interior_max = 0;
  int outer_count = 0;
  for (std::size_t i = 0; i < ball.size(); ++i) {
    float d = length(ball[i]);
    if (d < r - h) interior_max = std::max(interior_max, double(a.area[i]));
    if (d > r - kSpacing) {
      outer_sum += a.area[i];
      ++outer_count;
    }
  }
  const double outer_mean = outer_sum / outer_count;
  std::printf("ball R = %d: largest interior A_i / mean outer-layer A_i = %.2e\n", n, interior_max / outer_mean);
  EXPECT_LE(interior_max, 1e-3 * outer_mean);
}

// A liquid particle with weight w and density rho occupies V = w m / rho:
// halving both weights and densities leaves every volume, hence every
// area, as it was.
TEST(surface_area_Geometry, AdaptiveMassesEnterThroughTheirVolumes) {
  std::vector<Vec3> ball = lattice_ball(8, kSpacing);
  area_test::Areas full = surface_areas(ball, {}, kSpacing, 2, 1.0f, 1000.0f);
  area_test::Areas half = surface_areas(ball, {}, kSpacing, 2, 0.5f, 500.0f);
  for (std::size_t i = 0; i < ball.size(); ++i) ASSERT_NEAR(half.area[i], full.area[i], 1e-6f * full.area[i] + 1e-12f);
  area_test::Areas light = surface_areas(ball, {}, kSpacing, 2, 0.5f, 1000.0f);
  EXPECT_NEAR(light.total, 0.25 * full.total, 1e-6 * full.total);  // V and each V_j halve
}

// Where a liquid particle next to a single-layer wall with Akinci volumes
// comes to rest: the gap at which its density, liquid lattice above plus
// wall below, equals the rest density.
double rest_gap_over_wall(float spacing) {
  const CubicSplineKernel kernel = CubicSplineKernel::with_support(2.0f * spacing);
  const int reach = 3;
  double in_plane = 0, full = 0;
  for (int j = -reach; j <= reach; ++j)
    for (int i = -reach; i <= reach; ++i) {
      in_plane += kernel.W(spacing * std::sqrt(float(i * i + j * j)));
      for (int k = -reach; k <= reach; ++k) full += kernel.W(spacing * std::sqrt(float(i * i + j * j + k * k)));
    }
  const double wall_volume = 1.0 / in_plane, volume = double(spacing) * spacing * spacing;
  auto density_ratio = [&](double gap) {
    double sum = 0;
    for (int j = -reach; j <= reach; ++j)
      for (int i = -reach; i <= reach; ++i) {
        for (int k = 0; k <= reach; ++k) sum += volume * kernel.W(spacing * std::sqrt(float(i * i + j * j + k * k)));
        double d2 = double(spacing) * spacing * (i * i + j * j) + gap * gap;
        sum += wall_volume * kernel.W(static_cast<float>(std::sqrt(d2)));
      }
    return sum / (volume * full);
  };
  double lo = 0.5 * spacing, hi = 2.0 * spacing;  // denser than rest at lo, lighter at hi
  for (int it = 0; it < 50; ++it) {
    double mid = 0.5 * (lo + hi);
    (density_ratio(mid) > 1.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(surface_area_Wall, SlabOnWallExposesTopAndSidesOnly) {
  const int n = 32, layers = 3;
  const double l = n * kSpacing, top = l * l, sides = 4.0 * l * layers * kSpacing;
  std::vector<Vec3> wall = lattice_block(Vec3{-5 * kSpacing, -5 * kSpacing, 0}, n + 10, n + 10, 1, kSpacing);
  const double rest_gap = rest_gap_over_wall(kSpacing);
  std::printf("liquid rests %.3f spacings above a single-layer wall\n", rest_gap / kSpacing);
  for (double gap : {0.75 * kSpacing, 1.0 * kSpacing, rest_gap}) {
    std::vector<Vec3> slab = lattice_block(Vec3{0, 0, float(gap)}, n, n, layers, kSpacing);
    area_test::Areas alone = surface_areas(slab, {}, kSpacing);
    area_test::Areas on_wall = surface_areas(slab, wall, kSpacing);
    // Columns more than h from the slab's sides see only top and wall.
    double inner = 0;
    int inner_columns_per_side = 0;
    const float h = 2.0f * kSpacing;
    for (std::size_t i = 0; i < slab.size(); ++i) {
      Vec3 x = slab[i];
      if (x.x > h && x.x < (n - 1) * kSpacing - h && x.y > h && x.y < (n - 1) * kSpacing - h) inner += on_wall.area[i];
    }
    for (int i = 0; i < n; ++i)
      if (i * kSpacing > h && i * kSpacing < (n - 1) * kSpacing - h) ++inner_columns_per_side;
    const double inner_top = double(inner_columns_per_side) * inner_columns_per_side * kSpacing * kSpacing;
    std::printf("slab %dx%dx%d at gap %.3f spacings: free sum A / (2 top + sides) = %.4f; on wall sum A / (top + "
                "sides) = %.4f, inner columns sum A / their top = %.4f\n",
                n, n, layers, gap / kSpacing, alone.total / (2 * top + sides), on_wall.total / (top + sides),
                inner / inner_top);
    EXPECT_NEAR(on_wall.total / (top + sides), 1.0, 0.15) << "gap " << gap / kSpacing;
    EXPECT_NEAR(inner / inner_top, 1.0, 0.15) << "gap " << gap / kSpacing;
  }
}

}  // namespace
}  // namespace dp
