// Pressure projection (paper Eq. 1, Alg. 1 line 11): a random velocity field
// around obstacles comes out discretely divergence-free, in a closed box
// (singular Poisson problem) and with an open face.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

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

// The boundary conditions of Alg. 1 line 8 after whole steps: no flow
// through closed domain faces or the faces of rigid and liquid cells, the
// prescribed velocity on an inflow's faces. The expectation is read from
// the cells' kinds alone, face by face. The liquid moves a cell each step,
// so the walls change between steps, and buoyancy, confinement and
// advection push velocity onto the wall faces within each step.
TEST(air_Projection, WallAndInflowFacesHoldTheirPrescribedVelocityAfterEachStep) {
  CpuExec exec = test::air_exec();
  AirSettings s = test::quiet_air_box(16);
  s.buoyancy_beta = 0.0335f;
  s.vorticity_epsilon = 2.0f;
  s.open_face[static_cast<int>(AirFace::YMax)] = true;
  AirInflow in;
  in.box_min = Vec3{0.0f, 0.0f, 0.3f};
  in.box_max = Vec3{0.13f, 0.25f, 0.6f};
  in.velocity = Vec3{1.0f, 0.5f, -0.25f};
  in.temperature = 310.0f;
  s.inflows.push_back(in);
  test::SortedParticles rigid(exec, test::sphere_shell(Vec3{0.6f, 0.4f, 0.5f}, 0.15f, 0.01f), s.domain_min, s.domain_max,
                              0.02f);
  AirGrid<CpuExec> air(exec, s, Vec3{0, -9.81f, 0}, rigid.view());
  AirSnapshot state = air.snapshot();
  test::randomise_velocity(state, 1.0f, 5);
  air.set_velocity(state.u, state.v, state.w);
  const float dx = state.grid.dx;
  int wall_faces = 0, inflow_faces = 0;
  float free_speed = 0.0f;
  for (int step = 0; step < 6; ++step) {
    // A 3 x 3 x 3-cell block of liquid that moves one cell along z per step.
    std::vector<Vec3> liquid;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        for (int c = 0; c < 3; ++c) liquid.push_back(dx * Vec3{10.5f + a, 0.5f + b, 3.5f + c + step});
    test::SortedParticles drops(exec, liquid, s.domain_min, s.domain_max, 0.02f);
    air.classify(exec, drops.positions());
    air.step(exec, 0.01f);
    const AirSnapshot a = air.snapshot();
    const MacGrid& g = a.grid;
    const std::vector<float>* velocity[3] = {&a.u, &a.v, &a.w};
    for (int axis = 0; axis < 3; ++axis)
      for (int k = 0; k < g.face_n(axis, 2); ++k)
        for (int j = 0; j < g.face_n(axis, 1); ++j)
          for (int i = 0; i < g.face_n(axis, 0); ++i) {
            const int along = axis == 0 ? i : (axis == 1 ? j : k);
            const auto kind_at = [&](int side) -> int {  // -1: outside the domain
              const int d = side == 0 ? 1 : 0;
              if (side == 0 && along == 0) return -1;
              if (side == 1 && along == g.n(axis)) return -1;
              return a.kind[g.cell(i - (axis == 0) * d, j - (axis == 1) * d, k - (axis == 2) * d)];
            };
            bool wall = false, inflow = false;
            for (int side = 0; side < 2; ++side) {
              const int kind = kind_at(side);
              const bool open = kind < 0 && s.open_face[2 * axis + side];
              wall |= (kind < 0 && !open) || kind == kSolidCell || kind == kLiquidCell;
              inflow |= kind == kInflowCell;
            }
            const float u = (*velocity[axis])[g.face(axis, i, j, k)];
            if (wall) {
              ++wall_faces;
              ASSERT_EQ(u, 0.0f) << "step " << step << ", axis " << axis << " face " << i << " " << j << " " << k;
            } else if (inflow) {
              ++inflow_faces;
              ASSERT_EQ(u, in.velocity[axis]) << "step " << step << ", axis " << axis << " face " << i << " " << j << " " << k;
            } else {
              free_speed = std::max(free_speed, std::fabs(u));
            }
          }
    int liquid_cells = 0;
    for (auto kind : a.kind) liquid_cells += kind == kLiquidCell;
    ASSERT_GE(liquid_cells, 27) << "the block must occupy its cells";
  }
  RecordProperty("largest_free_face_speed", test::sci(free_speed));
  // The test bites only with a flow on the free faces and both kinds of
  // prescribed face present.
  EXPECT_GT(free_speed, 0.1f);
  EXPECT_GT(wall_faces, 0);
  EXPECT_GT(inflow_faces, 0);
}

}  // namespace
}  // namespace dp
