// The air step gathers and sums in a fixed order: its results are the same
// bits on one thread and on two (DESIGN §3), and in the launcher's baseline
// and AVX2 copies (cpu_isa.h).
#include <gtest/gtest.h>

#include <cstring>

#include "air_test_setups.h"

namespace dp {
namespace {

AirSnapshot run(int threads, CpuIsa isa = detect_cpu_isa(), AirAdvection advection = AirAdvection::MacCormack) {
  CpuExec exec(threads, isa);
  AirSettings s = test::quiet_air_box(16, 0.64f);
  s.buoyancy_alpha = -3.09f;
  s.buoyancy_beta = 0.0335f;
  s.vorticity_epsilon = 2.0f;
  s.vapor_diffusivity = 2.5e-5f;
  s.heat_diffusivity = 2.2e-5f;
  s.ambient_vapor = 0.005;
  s.advection = advection;
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
    air.classify(exec, liquid.positions());
    air.step(exec, 0.01f);
  }
  return air.snapshot();
}

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

void expect_same_bits(const AirSnapshot& a, const AirSnapshot& b) {
  EXPECT_TRUE(same_bits(a.vapor, b.vapor));
  EXPECT_TRUE(same_bits(a.temperature, b.temperature));
  EXPECT_TRUE(same_bits(a.u, b.u));
  EXPECT_TRUE(same_bits(a.v, b.v));
  EXPECT_TRUE(same_bits(a.w, b.w));
  EXPECT_EQ(a.ledger.open_out, b.ledger.open_out);
  EXPECT_EQ(a.ledger.inflow_gain, b.ledger.inflow_gain);
}

TEST(air_Determinism, OneAndTwoThreadsGiveTheSameBits) { expect_same_bits(run(1), run(2)); }

// Both advection schemes (the semi-Lagrangian one four points at a time),
// vorticity confinement, diffusion, the multigrid CG and the vapor fluxes,
// each loop compiled for SSE2 and for AVX2 without FMA.
TEST(air_Determinism, BaselineAndAvx2CopiesGiveTheSameBits) {
  if (!cpu_runs_avx2_copy()) GTEST_SKIP() << "this CPU or build has no AVX2 copy";
  for (const AirAdvection a : {AirAdvection::SemiLagrangian, AirAdvection::MacCormack}) {
    SCOPED_TRACE(a == AirAdvection::MacCormack ? "MacCormack" : "semi-Lagrangian");
    expect_same_bits(run(2, CpuIsa::Baseline, a), run(2, CpuIsa::Avx2, a));
  }
}

}  // namespace
}  // namespace dp
