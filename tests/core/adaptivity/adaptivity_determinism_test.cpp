// The adaptivity kernels gather and write only their own element, so the
// result arrays are bit-identical for any thread count.
#include <gtest/gtest.h>

#include <cstring>

#include "adaptivity_clouds.h"
#include "backend/cpu_exec.h"

namespace dp {
namespace {

using test::HostParticles;

template <class T>
bool bitwise_equal(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

HostParticles adapt_with_threads(int threads) {
  constexpr std::size_t kParticles = 5000;
  CpuExec exec(threads);
  auto particles = test::to_device<CpuExec>(test::random_weight_cloud(kParticles, 99));
  MassAdaptivity<CpuExec> adaptivity(test::grid_for_box(test::box_side(kParticles)));
  AdaptivityParameters p;
  p.search_radius = test::kSupport;
  p.max_rounds = 3;
  for (int call = 0; call < 5; ++call) adaptivity.adapt(exec, particles, p);
  return test::to_host(particles);
}

TEST(adaptivity_determinism, ResultArraysAreBitIdenticalForAnyThreadCount) {
  const HostParticles one = adapt_with_threads(1);
  ASSERT_LT(one.size(), 5000u);
  for (int threads : {2, 3}) {
    const HostParticles many = adapt_with_threads(threads);
    EXPECT_TRUE(bitwise_equal(one.position, many.position)) << threads << " threads";
    EXPECT_TRUE(bitwise_equal(one.velocity, many.velocity)) << threads << " threads";
    EXPECT_TRUE(bitwise_equal(one.temperature, many.temperature)) << threads << " threads";
    EXPECT_TRUE(bitwise_equal(one.units, many.units)) << threads << " threads";
    EXPECT_TRUE(bitwise_equal(one.id, many.id)) << threads << " threads";
    EXPECT_TRUE(bitwise_equal(one.extra, many.extra)) << threads << " threads";
  }
}

}  // namespace
}  // namespace dp
