// A ball of particles against two references nobody here wrote: the volume
// the particles stand for, and OpenVDB's own Zhu-Bridson rasterisation
// (points::rasterizeSmoothSpheres, "Animating Sand as a Fluid", Zhu &
// Bridson 2005) meshed by tools::volumeToMesh, on the same particles with
// the same radii, kernel radius and voxel size.
#include <gtest/gtest.h>
#include <openvdb/openvdb.h>
#include <openvdb/points/PointConversion.h>
#include <openvdb/points/PointRasterizeSDF.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <cmath>
#include <cstdio>

#include "liquid_surface.h"
#include "mesh_measures.h"
#include "mesh_topology.h"

namespace dp::mesh {
namespace {

struct Ball {
  double spacing = 0.1, radius = 1.0;
  LiquidParticles particles;
  Ball() {
    const int n = int(std::ceil(radius / spacing));
    // Off the lattice's axes on purpose: no symmetry of the grid helps.
    const Vec3d shift{0.0123, -0.0311, 0.0057};
    for (int k = -n; k <= n; ++k)
      for (int j = -n; j <= n; ++j)
        for (int i = -n; i <= n; ++i) {
          const Vec3d x = spacing * Vec3d{double(i), double(j), double(k)};
          if (length(x) > radius) continue;
          particles.position.push_back(x + shift);
          particles.radius.push_back(0.5 * spacing);
        }
  }
  double particles_volume() const { return double(particles.size()) * spacing * spacing * spacing; }
};

double triangle_fan_volume(const std::vector<openvdb::Vec3s>& p, const std::vector<openvdb::Vec3I>& triangles,
                           const std::vector<openvdb::Vec4I>& quads) {
  auto tet = [&](unsigned a, unsigned b, unsigned c) {
    const openvdb::Vec3d pa(p[a]), pb(p[b]), pc(p[c]);
    return pa.dot(pb.cross(pc)) / 6;
  };
  double v = 0;
  for (const auto& t : triangles) v += tet(t[0], t[1], t[2]);
  for (const auto& q : quads) v += tet(q[0], q[1], q[2]) + tet(q[0], q[2], q[3]);
  return std::abs(v);  // OpenVDB's winding is its own; the magnitude is the volume
}

double openvdb_volume(const Ball& ball, double kernel_radius, double voxel) {
  openvdb::initialize();
  std::vector<openvdb::Vec3R> positions;
  for (const Vec3d& x : ball.particles.position) positions.emplace_back(x.x, x.y, x.z);
  const openvdb::points::PointAttributeVector<openvdb::Vec3R> wrapper(positions);
  // Points are bucketed at the kernel radius; the distance is sampled at the voxel size.
  const auto point_transform = openvdb::math::Transform::createLinearTransform(kernel_radius);
  const auto index = openvdb::tools::createPointIndexGrid<openvdb::tools::PointIndexGrid>(wrapper, *point_transform);
  const auto points = openvdb::points::createPointDataGrid<openvdb::points::NullCodec, openvdb::points::PointDataGrid>(
      *index, wrapper, *point_transform);
  const auto sdf_transform = openvdb::math::Transform::createLinearTransform(voxel);
  const auto sdf = openvdb::points::rasterizeSmoothSpheres(*points, 0.5 * ball.spacing, kernel_radius, 3.0, sdf_transform);
  std::vector<openvdb::Vec3s> vertices;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(*sdf, vertices, triangles, quads, 0.0);
  return triangle_fan_volume(vertices, triangles, quads);
}

TEST(mesh_Ball, ClosedGenusZeroWithTheParticlesVolumeAndOpenVdbsVolume) {
  const Ball ball;
  const SurfaceParameters parameters = surface_parameters(ball.spacing, io::MeshSettings{});
  const LiquidSurface surface = liquid_surface(ball.particles, parameters);
  EXPECT_EQ(testing::orientation_problem(surface.mesh), "");
  EXPECT_EQ(testing::euler_characteristic(surface.mesh), 2);
  const double ours = enclosed_volume(surface.mesh), particles = ball.particles_volume();
  const double openvdb = openvdb_volume(ball, parameters.kernel_radius, parameters.voxel_size);
  std::printf("ball of %zu particles: ours %.5f m^3, particles %.5f m^3 (%+.2f %%), OpenVDB %.5f m^3 (%+.2f %%)\n",
              ball.particles.size(), ours, particles, 100 * (ours / particles - 1), openvdb, 100 * (ours / openvdb - 1));
  EXPECT_NEAR(ours, particles, 0.03 * particles);
  EXPECT_NEAR(ours, openvdb, 0.03 * openvdb);
}

}  // namespace
}  // namespace dp::mesh
