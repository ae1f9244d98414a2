// What the integrator relies on from the Embree scene: hits carry normals
// pointing to the object's outside, whatever the triangles' winding when
// the mesh has vertex normals; objects without triangles are left out.
#include <gtest/gtest.h>

#include <algorithm>

#include "render_scene.h"
#include "test_meshes.h"

namespace dp::render {
namespace {

dp::io::Material clear_water() {
  dp::io::Material m;
  m.type = dp::io::MaterialType::Dielectric;
  return m;
}

TEST(render_scene, CounterClockwiseFacetsFaceOutwards) {
  const RenderScene scene({{"box", test::box({-1, -1, -1}, {1, 1, 1}), clear_water(), ShadingNormals::Geometric}});
  const auto hit = scene.intersect({{0, 0, 5}, {0, 0, -1}});
  ASSERT_TRUE(hit);
  EXPECT_FLOAT_EQ(hit->distance, 4);
  EXPECT_FLOAT_EQ(hit->geometric_normal.z, 1);
  EXPECT_FLOAT_EQ(hit->shading_normal.z, 1);
}

TEST(render_scene, VertexNormalsDecideOutsideWhateverTheWinding) {
  dp::io::TriangleMesh sphere = test::icosphere({0, 0, 0}, 1, 2);
  for (auto& t : sphere.triangles) std::swap(t[1], t[2]);  // clockwise seen from outside
  const RenderScene scene({{"drop", sphere, clear_water(), ShadingNormals::Interpolated}});
  const Ray ray{{0.3f, 0.2f, 5}, {0, 0, -1}};
  const auto hit = scene.intersect(ray);
  ASSERT_TRUE(hit);
  EXPECT_GT(hit->geometric_normal.z, 0);
  // Smooth shading: the normal of the true sphere at the hit, to the facets' accuracy.
  const Vec3 exact = normalize(hit->position);
  EXPECT_GT(dot(hit->shading_normal, exact), 0.9999f);
}

TEST(render_scene, ObjectsWithoutTrianglesAreLeftOut) {
  const RenderScene scene({{"liquid", dp::io::TriangleMesh{}, clear_water(), ShadingNormals::Interpolated}});
  EXPECT_FALSE(scene.intersect({{0, 0, 5}, {0, 0, -1}}));
}

}  // namespace
}  // namespace dp::render
