// Properties of the surface area kernel that hold for any arrangement:
// determinism across thread counts, the flat-face calibration, and the
// clamped wall cancellation.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "area_scene.h"
#include "sph/surface_tension_akinci2013.h"

namespace dp {
namespace {

constexpr float kSpacing = 0.01f;

// A disordered liquid with adaptive weights and densities above a
// disordered wall.
std::vector<float> disordered_areas(int threads, bool from_akinci_normals = false) {
  CpuExec exec(threads);
  const CubicSplineKernel kernel = CubicSplineKernel::with_support(2.0f * kSpacing);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<Vec3> pl, pw;
  for (int i = 0; i < 3000; ++i) pl.push_back(Vec3{0.12f * u(rng), 0.12f * u(rng), 0.01f + 0.1f * u(rng)});
  for (int i = 0; i < 1500; ++i) pw.push_back(Vec3{0.12f * u(rng), 0.12f * u(rng), 0.01f * u(rng)});
  const UniformGrid grid = area_test::grid_around({pl, pw}, kernel.h);
  area_test::SortedSet l = area_test::sort_into(exec, pl, grid), w = area_test::sort_into(exec, pw, grid);
  std::vector<float> wall_volume = area_test::akinci_volumes(w, kernel);
  std::vector<MassUnits> units;
  std::vector<float> density, area(pl.size());
  for (std::size_t i = 0; i < pl.size(); ++i) {
    units.push_back(static_cast<MassUnits>((0.2f + 0.8f * u(rng)) * kFullParticleUnits));
    density.push_back(900.0f + 200.0f * u(rng));
  }
  std::vector<Vec3> normal(pl.size());
  exec.parallel_for(pl.size(), ComputeSurfaceNormal{l.view(), units.data(), density.data(), kernel, 1e-3f, normal.data()});
  exec.parallel_for(pl.size(), ComputeSurfaceArea{l.view(), units.data(), density.data(), 1e-3f, w.view(),
                                                  wall_volume.data(), true, kernel,
                                                  flat_face_area_calibration(kernel, kSpacing), area.data(),
                                                  from_akinci_normals ? normal.data() : nullptr});
  return area;
}

TEST(surface_area_Determinism, AreasAreBitIdenticalForAnyThreadCount) {
  std::vector<float> one = disordered_areas(1);
  for (int threads : {2, 3, 8}) {
    std::vector<float> many = disordered_areas(threads);
    ASSERT_EQ(one.size(), many.size());
    EXPECT_EQ(std::memcmp(one.data(), many.data(), one.size() * sizeof(float)), 0) << threads << " threads";
  }
}

// The step reads the colour gradient from Akinci 2013's normals
// (h sum_j V_j grad W_ij) instead of summing it twice: the same areas up to
// the rounding of the factor h.
TEST(surface_area_Determinism, AreasFromAkinciNormalsEqualTheDirectSum) {
  std::vector<float> direct = disordered_areas(2), shared = disordered_areas(2, true);
  ASSERT_EQ(direct.size(), shared.size());
  for (std::size_t i = 0; i < direct.size(); ++i) EXPECT_NEAR(shared[i], direct[i], 1e-5f * direct[i] + 1e-12f) << i;
}

// The calibration is exact by construction for a flat lattice face: a
// particle in the top layer of a thick slab, away from its sides, gets one
// lattice cell of area; the layer below gets none.
TEST(surface_area_Calibration, FlatFaceParticleGetsOneCell) {
  const int n = 12, layers = 5;
  std::vector<Vec3> slab = area_test::lattice_block(Vec3{}, n, n, layers, kSpacing);
  area_test::Areas a = area_test::surface_areas(slab, {}, kSpacing);
  auto at = [&](int i, int j, int k) { return a.area[(static_cast<std::size_t>(k) * n + j) * n + i]; };
  const float cell = kSpacing * kSpacing;
  EXPECT_NEAR(at(n / 2, n / 2, layers - 1), cell, 1e-5f * cell);
  EXPECT_NEAR(at(n / 2, n / 2, 0), cell, 1e-5f * cell);
  EXPECT_LT(at(n / 2, n / 2, layers - 2), 1e-5f * cell);
}

TEST(surface_area_Calibration, DependsOnTheRatioOfSupportToSpacingOnly) {
  const float a = flat_face_area_calibration(CubicSplineKernel::with_support(0.02f), 0.01f);
  const float b = flat_face_area_calibration(CubicSplineKernel::with_support(0.5f), 0.25f);
  EXPECT_NEAR(a, b, 1e-5f * a);
  EXPECT_GT(a, 1.5f);  // about 2: particles see only the liquid half of the interface
  EXPECT_LT(a, 2.5f);
}

TEST(surface_area_Wall, HidesAtMostTheComponentFacingAway) {
  const Vec3 up{0, 0, 1};
  // A gradient pointing towards the wall is not the wall's to hide.
  Vec3 none = wall_hidden_part(Vec3{0.3f, 0, -0.5f}, up, 2.0f);
  EXPECT_EQ(length(none), 0.0f);
  // A strong wall removes the whole facing component, never the tangential one.
  Vec3 all = wall_hidden_part(Vec3{0.3f, 0, 0.5f}, up, 2.0f);
  EXPECT_FLOAT_EQ(all.z, 0.5f);
  EXPECT_EQ(all.x, 0.0f);
  // A weak (distant) wall removes only as much as its own gradient.
  Vec3 some = wall_hidden_part(Vec3{0.3f, 0, 0.5f}, up, 0.2f);
  EXPECT_FLOAT_EQ(some.z, 0.2f);
}

}  // namespace
}  // namespace dp
