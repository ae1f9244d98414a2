// The mesh of a frame must not depend on how many threads made it.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cstring>
#include <random>

#include "liquid_surface.h"
#include "marching_cubes.h"
#include "liquid_field.h"
#include "wall_drop.h"
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
    p.velocity.push_back({uniform() - 0.5, 0, uniform() - 0.5});
  }
  return p;
}

struct Result {
  ScalarGrid field;
  SurfaceMesh mesh;
};

// With `floor`, the blob rests on a wall below it and is corrected there
// with dynamic contact angles (its particles move).
Result mesh_with_threads(const LiquidParticles& p, int threads, bool floor = false) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  const double spacing = 0.04;
  const SurfaceParameters parameters = surface_parameters(spacing, io::MeshSettings{});
  const GridBox box = zhu_bridson_grid_box(p, parameters.kernel_radius, parameters.voxel_size);
  const RigidWalls walls({testing::floor_mesh(-0.47, 2.0)});
  const ContactAngleCorrection_HochstetterKolb2017 correction(walls, {{{1.0, 0.5, 0.4}}, 1.0});
  Result r{sample_liquid_field(p, parameters.kernel_radius, box, floor ? &correction : nullptr), {}};
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

TEST(mesh_Determinism, WallCorrectionsAreThreadCountIndependentToo) {
  const LiquidParticles p = random_blob();
  const Result one = mesh_with_threads(p, 1, true), two = mesh_with_threads(p, 2, true);
  const Result plain = mesh_with_threads(p, 2, false);
  ASSERT_FALSE(one.mesh.triangles.empty());
  EXPECT_FALSE(same_bits(one.field.values, plain.field.values)) << "the floor changed nothing: the test tests nothing";
  EXPECT_TRUE(same_bits(one.field.values, two.field.values));
  EXPECT_TRUE(same_bits(one.mesh.position, two.mesh.position));
  EXPECT_TRUE(same_bits(one.mesh.triangles, two.mesh.triangles));
}

// The block gather and the per-point neighbour search are two ways to the
// same sums: they agree at every node, active block or not.
TEST(mesh_NarrowBand, BlockFieldEqualsPointwiseZhuBridson) {
  const LiquidParticles p = random_blob();
  const double kernel_radius = 0.08;
  const GridBox box = zhu_bridson_grid_box(p, kernel_radius, 0.01);
  LiquidFieldCounts counts;
  const ScalarGrid grid = sample_liquid_field(p, kernel_radius, box, nullptr, &counts);
  const ZhuBridsonField reference(p, kernel_radius);
  for (int k = 0; k < box.nodes[2]; k += 3)
    for (int j = 0; j < box.nodes[1]; ++j)
      for (int i = 0; i < box.nodes[0]; ++i)
        ASSERT_NEAR(grid.at(i, j, k), reference.distance(box.node_position(i, j, k)), 1e-6 * kernel_radius)
            << i << " " << j << " " << k;
  EXPECT_LT(counts.active_blocks, counts.blocks) << "the band skipped no block";
}

}  // namespace
}  // namespace dp::mesh
