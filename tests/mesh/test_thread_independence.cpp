// The mesh of a frame must not depend on how many threads made it.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cstring>
#include <random>

#include "liquid_surface.h"
#include "marching_cubes.h"
#include "liquid_field.h"
#include "zhu_bridson.h"

namespace dp::mesh {
namespace {

// A lumpy blob: random particles, so that sums over neighbours mix many
// magnitudes and any change in summation order would show in the bits.
LiquidParticles random_blob() {
  std::mt19937 random(20170707);  // mt19937's sequence is fixed by the standard; its distributions are not
  auto uniform = [&] { return double(random()) / double(std::mt19937::max()); };
  LiquidParticles p;
  for (int n = 0; n < 2000; ++n) {
    const Vec3d x{uniform() - 0.5, uniform() - 0.5, uniform() - 0.5};
    if (length(x) > 0.5) continue;
    p.position.push_back(x);
    p.radius.push_back(0.02 * (0.8 + 0.4 * uniform()));
  }
  return p;
}

struct Result {
  ScalarGrid field;
  SurfaceMesh mesh;
};

Result mesh_with_threads(const LiquidParticles& p, int threads) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  const double spacing = 0.04;
  const SurfaceParameters parameters = surface_parameters(spacing, io::MeshSettings{});
  const GridBox box = zhu_bridson_grid_box(p, parameters.kernel_radius, parameters.voxel_size);
  Result r{sample_liquid_field(p, parameters.kernel_radius, box, nullptr), {}};
  r.mesh = marching_cubes(r.field);
  return r;
}

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

TEST(mesh_Determinism, OneAndTwoThreadsGiveBitIdenticalFieldAndMesh) {
  const LiquidParticles p = random_blob();
  const Result one = mesh_with_threads(p, 1), two = mesh_with_threads(p, 2);
  ASSERT_FALSE(one.mesh.triangles.empty());
  EXPECT_TRUE(same_bits(one.field.values, two.field.values));
  EXPECT_TRUE(same_bits(one.mesh.position, two.mesh.position));
  EXPECT_TRUE(same_bits(one.mesh.normal, two.mesh.normal));
  EXPECT_TRUE(same_bits(one.mesh.triangles, two.mesh.triangles));
}

}  // namespace
}  // namespace dp::mesh
