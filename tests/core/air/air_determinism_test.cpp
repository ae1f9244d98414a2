// The air step gathers and sums in a fixed order: its results are the same
// bits on one thread and on two (DESIGN §3).
#include <gtest/gtest.h>

#include <cstring>

#include "air_test_setups.h"

namespace dp {
namespace {

AirSnapshot run(int threads) {
  CpuExec exec(threads);
  AirSettings s = test::quiet_air_box(16, 0.64f);
  s.buoyancy_alpha = -3.09f;
  s.buoyancy_beta = 0.0335f;
  s.vorticity_epsilon = 2.0f;
  s.vapor_diffusivity = 2.5e-5f;
  s.heat_diffusivity = 2.2e-5f;
  s.ambient_vapor = 0.005;
  s.advection = AirAdvection::MacCormack;
  s.open_face[static_cast<int>(AirFace::YMax)] = true;
  AirInflow in;
  in.box_min = Vec3{0.0f, 0.0f, 0.2f};
  in.box_max = Vec3{0.1f, 0.2f, 0.4f};
  in.velocity = Vec3{1.0f, 0.5f, 0.0f};
  in.temperature = 310.0f;
  in.vapor = 0.02;
  s.inflows.push_back(in);
  test::SortedParticles rigid(exec, test::sphere_shell(Vec3{0.35f, 0.3f, 0.3f}, 0.12f, 0.01f), s.domain_min,
                              s.domain_max, 0.02f);
  test::SortedParticles liquid(exec, {Vec3{0.5f, 0.05f, 0.5f}, Vec3{0.52f, 0.05f, 0.5f}}, s.domain_min, s.domain_max, 0.02f);
  AirGrid<CpuExec> air(exec, s, Vec3{0, -9.81f, 0}, rigid.view());
  for (int n = 0; n < 8; ++n) {
    air.classify(exec, liquid.view());
    air.step(exec, 0.01f);
  }
  return air.snapshot();
}

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

TEST(air_Determinism, OneAndTwoThreadsGiveTheSameBits) {
  const AirSnapshot a = run(1), b = run(2);
  EXPECT_TRUE(same_bits(a.vapor, b.vapor));
  EXPECT_TRUE(same_bits(a.temperature, b.temperature));
  EXPECT_TRUE(same_bits(a.u, b.u));
  EXPECT_TRUE(same_bits(a.v, b.v));
  EXPECT_TRUE(same_bits(a.w, b.w));
  EXPECT_EQ(a.ledger.open_out, b.ledger.open_out);
  EXPECT_EQ(a.ledger.inflow_gain, b.ledger.inflow_gain);
}

}  // namespace
}  // namespace dp
