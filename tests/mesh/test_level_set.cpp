// The level set dewpoint-mesh can write (mesh/liquid_level_set.h), meshed by
// OpenVDB's own volumeToMesh, against our marching-cubes mesh of the same
// field: the enclosed volume within 1 % and the contact angle at a floor
// within 2 degrees, for the single-particle drops of paper Fig. 3 at
// alpha_base 45, 90 and 135 degrees.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include <openvdb/tools/VolumeToMesh.h>

#include "liquid_level_set.h"
#include "mesh_measures.h"
#include "wall_drop.h"

namespace dp::mesh {
namespace {

// volumeToMesh's quads split into triangles, wound so that the enclosed
// volume is positive (outward normals), as our meshes are.
SurfaceMesh openvdb_mesh(const openvdb::FloatGrid& grid) {
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(grid, points, triangles, quads, 0.0);
  SurfaceMesh m;
  for (const auto& p : points) m.position.push_back(Vec3d{p.x(), p.y(), p.z()});
  for (const auto& t : triangles) m.triangles.push_back({t[0], t[1], t[2]});
  for (const auto& q : quads) {
    m.triangles.push_back({q[0], q[1], q[2]});
    m.triangles.push_back({q[0], q[2], q[3]});
  }
  if (enclosed_volume(m) < 0)
    for (auto& t : m.triangles) std::swap(t[1], t[2]);
  return m;
}

class mesh_LevelSet : public ::testing::TestWithParam<double> {};

TEST_P(mesh_LevelSet, OpenVdbMeshOfTheGridMatchesOurMesh) {
  testing::WallDrop drop;
  drop.angles.base = GetParam() * M_PI / 180;
  ScalarGrid field;
  const SurfaceMesh ours = drop.mesh(true, &field);
  const openvdb::FloatGrid::Ptr grid = liquid_level_set(field);
  EXPECT_EQ(grid->getGridClass(), openvdb::GRID_LEVEL_SET);
  EXPECT_EQ(grid->getName(), "surface");
  const SurfaceMesh theirs = openvdb_mesh(*grid);
  ASSERT_FALSE(theirs.triangles.empty());

  const double v_ours = enclosed_volume(ours), v_theirs = enclosed_volume(theirs);
  const double a_ours = testing::contact_angle_deg(ours, drop), a_theirs = testing::contact_angle_deg(theirs, drop);
  std::printf("alpha_base %.0f: volume %.6g vs %.6g m^3 (%.3f %%), angle %.2f vs %.2f degrees\n", GetParam(), v_ours,
              v_theirs, 100 * (v_theirs / v_ours - 1), a_ours, a_theirs);
  EXPECT_NEAR(v_theirs, v_ours, 0.01 * v_ours);
  EXPECT_NEAR(a_theirs, a_ours, 2.0);
}

INSTANTIATE_TEST_SUITE_P(Angles, mesh_LevelSet, ::testing::Values(45.0, 90.0, 135.0));

// Away from the surface the grid holds OpenVDB's level-set convention:
// -band inside, +band outside, whatever the sampled field held there.
TEST(mesh_LevelSet, FarVoxelsHoldPlusOrMinusTheBand) {
  testing::WallDrop drop;
  ScalarGrid field;
  drop.mesh(true, &field);
  const openvdb::FloatGrid::Ptr grid = liquid_level_set(field);
  const float band = kLevelSetHalfWidth * static_cast<float>(field.box.voxel_size);
  const auto& transform = grid->transform();
  auto value_at = [&](Vec3d p) {
    const openvdb::Coord c = transform.worldToIndexNodeCentered(openvdb::Vec3d(p.x, p.y, p.z));
    return grid->getConstAccessor().getValue(c);
  };
  const Vec3d centre = drop.centre();
  EXPECT_FLOAT_EQ(value_at(centre + Vec3d{0, 0.2 * drop.radius, 0}), -band);
  EXPECT_FLOAT_EQ(value_at(centre + Vec3d{3 * drop.radius, 0, 0}), band);
}

}  // namespace
}  // namespace dp::mesh
