// Marching cubes on analytic signed distances, against closed-form volume,
// area and topology.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "marching_cubes.h"
#include "mesh_measures.h"
#include "mesh_topology.h"
#include "sample_grid.h"

namespace dp::mesh {
namespace {

constexpr double kPi = std::numbers::pi;

// Off the lattice on purpose: no symmetry of the grid helps the result.
const Vec3d kCentre{0.013, -0.021, 0.007};

SurfaceMesh sphere_mesh(double radius, double voxel) {
  const Vec3d reach{radius, radius, radius};
  const GridBox box = covering_grid(kCentre - reach, kCentre + reach, voxel, 2 * voxel);
  return marching_cubes(sample_grid(box, [&](Vec3d x) { return length(x - kCentre) - radius; }));
}

// A ring of radius `major` about the y axis, tube radius `minor`.
SurfaceMesh torus_mesh(double major, double minor, double voxel) {
  const Vec3d reach{major + minor, minor, major + minor};
  const GridBox box = covering_grid(kCentre - reach, kCentre + reach, voxel, 2 * voxel);
  return marching_cubes(sample_grid(box, [&](Vec3d x) {
    const Vec3d p = x - kCentre;
    const double ring = std::hypot(p.x, p.z) - major;
    return std::hypot(ring, p.y) - minor;
  }));
}

TEST(mesh_MarchingCubes, SphereIsClosedOrientedAndGenusZero) {
  const SurfaceMesh mesh = sphere_mesh(1.0, 0.05);
  ASSERT_FALSE(mesh.triangles.empty());
  EXPECT_EQ(testing::orientation_problem(mesh), "");
  EXPECT_EQ(testing::euler_characteristic(mesh), 2);
}

TEST(mesh_MarchingCubes, SphereVolumeAndAreaMatchClosedForm) {
  const double r = 1.0;
  const SurfaceMesh mesh = sphere_mesh(r, 0.05);
  const double volume = 4.0 / 3.0 * kPi * r * r * r, area = 4 * kPi * r * r;
  EXPECT_NEAR(enclosed_volume(mesh), volume, 0.01 * volume);
  EXPECT_NEAR(surface_area(mesh), area, 0.02 * area);
}

TEST(mesh_MarchingCubes, SphereVerticesAndNormalsLieOnTheSphere) {
  const SurfaceMesh mesh = sphere_mesh(1.0, 0.05);
  ASSERT_EQ(mesh.normal.size(), mesh.position.size());
  for (std::size_t v = 0; v < mesh.position.size(); ++v) {
    const Vec3d radial = mesh.position[v] - kCentre;
    // Linear interpolation of a sphere's distance errs by O(h^2 / r).
    ASSERT_NEAR(length(radial), 1.0, 2e-3) << "vertex " << v;
    ASSERT_NEAR(length(mesh.normal[v]), 1.0, 1e-9) << "vertex " << v;
    ASSERT_GT(dot(mesh.normal[v], normalized(radial)), 0.999) << "vertex " << v << " normal is not outward radial";
  }
}

TEST(mesh_MarchingCubes, TorusIsClosedWithEulerCharacteristicZero) {
  const double major = 1.0, minor = 0.4;
  const SurfaceMesh mesh = torus_mesh(major, minor, 0.05);
  EXPECT_EQ(testing::orientation_problem(mesh), "");
  EXPECT_EQ(testing::euler_characteristic(mesh), 0);
  const double volume = 2 * kPi * kPi * major * minor * minor;
  EXPECT_NEAR(enclosed_volume(mesh), volume, 0.01 * volume);
}

TEST(mesh_MarchingCubes, FieldWithoutInsideGivesEmptyMesh) {
  const GridBox box = covering_grid({0, 0, 0}, {1, 1, 1}, 0.25, 0);
  const SurfaceMesh mesh = marching_cubes(sample_grid(box, [](Vec3d) { return 1.0; }));
  EXPECT_TRUE(mesh.position.empty());
  EXPECT_TRUE(mesh.triangles.empty());
}

}  // namespace
}  // namespace dp::mesh
