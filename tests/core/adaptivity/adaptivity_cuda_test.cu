// The adaptivity driver on the CUDA backend (label gpu): the same
// conservation laws as on the CPU, and the same pairing. Skipped, with the
// reason, where no GPU is present.
#include <gtest/gtest.h>

#include <unordered_set>

#include "adaptivity_clouds.h"
#include "adaptivity_cpu_reference.h"
#include "backend/cuda_exec.cuh"
#include "backend/device.h"

namespace dp {
namespace {

using test::HostParticles;

class adaptivity_cuda : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string why;
    if (cuda_device_count(&why) == 0) GTEST_SKIP() << "no GPU: " << why;
  }
};

AdaptivityParameters one_round() {
  AdaptivityParameters p;
  p.search_radius = test::kSupport;
  p.max_rounds = 1;
  return p;
}

TEST_F(adaptivity_cuda, FiftyRoundsConserveMassExactlyAndMomentum) {
  constexpr std::size_t kParticles = 5000;
  const HostParticles start = test::random_weight_cloud(kParticles, 2017);
  const test::Totals before = test::totals_of(start);
  CudaExec exec(0);
  auto particles = test::to_device<CudaExec>(start);
  MassAdaptivity<CudaExec> adaptivity(test::grid_for_box(test::box_side(kParticles)));
  std::size_t merges = 0;
  for (int round = 0; round < 50; ++round) {
    const std::size_t n = particles.size();
    AdaptivityResult r = adaptivity.adapt(exec, particles, one_round());
    merges += r.merges;
    EXPECT_EQ(r.removed_units, 0);
    EXPECT_EQ(particles.size(), n - r.merges);
  }
  const HostParticles h = test::to_host(particles);
  const test::Totals after = test::totals_of(h);
  EXPECT_EQ(after.units, before.units);
  EXPECT_GT(merges, 0u);
  for (MassUnits u : h.units) {
    ASSERT_GT(u, 0u);
    ASSERT_LE(u, kFullParticleUnits);
  }
  EXPECT_EQ(std::unordered_set<std::uint32_t>(h.id.begin(), h.id.end()).size(), h.size());
  EXPECT_LT(test::distance(after.momentum, before.momentum) / before.momentum_scale, 1e-6);
  EXPECT_LT(test::distance(after.first_moment, before.first_moment) / test::norm(before.first_moment), 1e-6);
}

TEST_F(adaptivity_cuda, FirstRoundPairsAsOnTheCpu) {
  // One round from the same input: sorting, partner choice and the integer
  // units agree exactly; blended floats may differ by FMA contraction.
  constexpr std::size_t kParticles = 5000;
  const HostParticles start = test::random_weight_cloud(kParticles, 7);
  const UniformGrid grid = test::grid_for_box(test::box_side(kParticles));
  const test::CpuReference cpu = test::adapt_on_cpu(start, grid, one_round());
  CudaExec gpu(0);
  auto on_gpu = test::to_device<CudaExec>(start);
  AdaptivityResult rg = adapt_particle_masses(gpu, on_gpu, grid, one_round());
  EXPECT_EQ(cpu.result.merges, rg.merges);
  EXPECT_EQ(cpu.result.redistributions, rg.redistributions);
  const HostParticles& hc = cpu.particles;
  const HostParticles hg = test::to_host(on_gpu);
  ASSERT_EQ(hc.size(), hg.size());
  EXPECT_EQ(hc.id, hg.id);
  EXPECT_EQ(hc.units, hg.units);
  for (std::size_t i = 0; i < hc.size(); ++i) EXPECT_NEAR(hc.velocity[i].x, hg.velocity[i].x, 1e-6f);
}

}  // namespace
}  // namespace dp
