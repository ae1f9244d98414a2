// Pressure projection (paper Eq. 1, Alg. 1 line 11): a random velocity field
// around obstacles comes out discretely divergence-free, in a closed box
// (singular Poisson problem) and with an open face.
#include <gtest/gtest.h>

#include "air_test_setups.h"

namespace dp {
namespace {

AirGrid<CpuExec> grid_with_obstacles(const CpuExec& exec, AirSettings s) {
  // A sphere shell (an enclosed air pocket inside) and a slab of particles.
  std::vector<Vec3> rigid = test::sphere_shell(Vec3{0.4f, 0.45f, 0.5f}, 0.18f, 0.01f);
  for (float x = 0.6f; x < 0.9f; x += 0.01f)
    for (float z = 0.1f; z < 0.7f; z += 0.01f) rigid.push_back(Vec3{x, 0.8f, z});
  test::SortedParticles set(exec, rigid, Vec3{0, 0, 0}, Vec3{1, 1, 1}, 0.02f);
  s.projection_tolerance = 1e-6f;
  return AirGrid<CpuExec>(exec, s, Vec3{0, -9.81f, 0}, set.view());
}

double divergence_after_projection(AirSettings s, int* iterations) {
  CpuExec exec = test::air_exec();
  AirGrid<CpuExec> air = grid_with_obstacles(exec, s);
  AirSnapshot state = air.snapshot();
  test::randomise_velocity(state, 1.0f, 7);
  air.set_velocity(state.u, state.v, state.w);
  const PcgResult r = air.project(exec);
  *iterations = r.iterations;
  EXPECT_LE(r.relative_residual, 1e-6f);
  AirSnapshot after = air.snapshot();
  int solid = 0;
  for (auto k : after.kind) solid += k == kSolidCell;
  EXPECT_GT(solid, 100) << "the obstacles should occupy cells";
  return test::relative_divergence(after);
}

TEST(air_Projection, RandomFieldInClosedBoxBecomesDivergenceFree) {
  int iterations = 0;
  const double d = divergence_after_projection(test::quiet_air_box(32), &iterations);
  RecordProperty("relative_divergence", test::sci(d));
  RecordProperty("iterations", iterations);
  EXPECT_LE(d, 1e-4);
  EXPECT_LT(iterations, 60);
}

TEST(air_Projection, RandomFieldWithOpenTopBecomesDivergenceFree) {
  AirSettings s = test::quiet_air_box(32);
  s.open_face[static_cast<int>(AirFace::YMax)] = true;
  s.open_face[static_cast<int>(AirFace::XMin)] = true;
  int iterations = 0;
  const double d = divergence_after_projection(s, &iterations);
  RecordProperty("relative_divergence", test::sci(d));
  EXPECT_LE(d, 1e-4);
  EXPECT_LT(iterations, 60);
}

}  // namespace
}  // namespace dp
