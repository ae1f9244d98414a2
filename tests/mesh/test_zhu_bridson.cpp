// The Zhu-Bridson field of paper Eq. 19 against its closed forms: one
// particle is a sphere of its own radius; a ball of particles on a lattice
// encloses the particles' volume.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "liquid_surface.h"
#include "marching_cubes.h"
#include "mesh_measures.h"
#include "mesh_topology.h"
#include "zhu_bridson.h"

namespace dp::mesh {
namespace {

LiquidParticles one_particle(Vec3d at, double radius) {
  LiquidParticles p;
  p.position.push_back(at);
  p.radius.push_back(radius);
  return p;
}

TEST(mesh_ZhuBridson, KernelIsOneMinusSSquaredCubedInsideAndZeroOutside) {
  EXPECT_DOUBLE_EQ(zhu_bridson_kernel(0.0), 1.0);
  EXPECT_DOUBLE_EQ(zhu_bridson_kernel(0.25), 0.75 * 0.75 * 0.75);
  EXPECT_EQ(zhu_bridson_kernel(1.0), 0.0);
  EXPECT_EQ(zhu_bridson_kernel(4.0), 0.0);
}

TEST(mesh_ZhuBridson, SingleParticleFieldIsDistanceMinusRadius) {
  const Vec3d centre{0.3, -1.2, 2.5};
  const double r = 0.5, kernel_radius = 2.0;
  const LiquidParticles p = one_particle(centre, r);
  const ZhuBridsonField field(p, kernel_radius);
  const Vec3d offsets[] = {{0, 0, 0}, {0.1, 0, 0}, {0, -0.5, 0}, {0.3, 0.4, -0.2}, {1.1, -0.9, 0.7}, {0, 0, 1.99}};
  for (const Vec3d& d : offsets) EXPECT_NEAR(field.distance(centre + d), length(d) - r, 1e-12);
  // Beyond R there are no weights; the point is outside at distance R.
  EXPECT_EQ(field.distance(centre + Vec3d{2.001, 0, 0}), kernel_radius);
  EXPECT_EQ(field.distance(centre + Vec3d{50, 60, -70}), kernel_radius);
}

TEST(mesh_ZhuBridson, SingleParticleMeshIsSphereOfParticleRadius) {
  const Vec3d centre{0.31, -0.17, 0.05};
  const double r = 0.5;
  const LiquidParticles p = one_particle(centre, r);
  const SurfaceParameters parameters{r, 2.0, 0.025};
  const LiquidSurface surface = liquid_surface(p, parameters);
  ASSERT_FALSE(surface.mesh.triangles.empty());
  EXPECT_EQ(testing::orientation_problem(surface.mesh), "");
  EXPECT_EQ(testing::euler_characteristic(surface.mesh), 2);
  for (const Vec3d& x : surface.mesh.position) ASSERT_NEAR(length(x - centre), r, 2e-3);
  const double volume = 4.0 / 3.0 * std::numbers::pi * r * r * r;
  EXPECT_NEAR(enclosed_volume(surface.mesh), volume, 0.01 * volume);
}

TEST(mesh_ZhuBridson, ParticleRadiusFollowsCubeRootOfWeight) {
  io::PlyData ply;
  ply.vertex_count = 2;
  ply.add("x", io::PlyType::Float32, {0, 1});
  ply.add("y", io::PlyType::Float32, {0, 0});
  ply.add("z", io::PlyType::Float32, {0, 0});
  ply.add("weight", io::PlyType::Float32, {1, 8});
  const LiquidParticles p = liquid_particles_from_ply(ply, 0.25);
  EXPECT_DOUBLE_EQ(p.radius[0], 0.25);
  EXPECT_DOUBLE_EQ(p.radius[1], 0.5);
}

TEST(mesh_ZhuBridson, ParticlesWithoutWeightPropertyHaveNominalRadius) {
  io::PlyData ply;
  ply.vertex_count = 1;
  for (const char* axis : {"x", "y", "z"}) ply.add(axis, io::PlyType::Float32, {0.5});
  const LiquidParticles p = liquid_particles_from_ply(ply, 0.25);
  EXPECT_DOUBLE_EQ(p.radius[0], 0.25);
}

// Lattice points of spacing s within a ball, each standing for a cube of
// liquid of volume s^3, meshed with the scene defaults (r = s/2, R = 2s,
// two voxels per radius).
TEST(mesh_ZhuBridson, LatticeBallEnclosesTheParticlesVolume) {
  const double s = 0.1, ball = 1.0;
  LiquidParticles p;
  const int n = int(std::ceil(ball / s));
  for (int k = -n; k <= n; ++k)
    for (int j = -n; j <= n; ++j)
      for (int i = -n; i <= n; ++i) {
        const Vec3d x{i * s, j * s, k * s};
        if (length(x) > ball) continue;
        p.position.push_back(x);
        p.radius.push_back(0.5 * s);
      }
  const SurfaceParameters parameters = surface_parameters(s, io::MeshSettings{});
  const LiquidSurface surface = liquid_surface(p, parameters);
  EXPECT_EQ(testing::orientation_problem(surface.mesh), "");
  EXPECT_EQ(testing::euler_characteristic(surface.mesh), 2);
  const double particles_volume = double(p.size()) * s * s * s;
  EXPECT_NEAR(enclosed_volume(surface.mesh), particles_volume, 0.05 * particles_volume);
}

}  // namespace
}  // namespace dp::mesh
