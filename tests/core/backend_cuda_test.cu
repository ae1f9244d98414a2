// The CUDA launcher's reductions and sweeps against CpuExec (label gpu;
// skipped, with the reason, where no GPU is present). Sums are compared
// bitwise: both backends add in the order of blocked_sum.h, and the values
// summed involve no multiplication the GPU could contract into an FMA.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "backend/cpu_exec.h"
#include "backend/cuda_exec.cuh"
#include "cuda_test_support.cuh"

namespace dp {
namespace {

class CudaBackend : public test::RequiresGpu {};

struct ValueOf {
  const float* v;
  DP_HD float operator()(std::size_t i) const { return v[i]; }
};
struct IsAbove {
  const float* v;
  float bound;
  DP_HD bool operator()(std::size_t i) const { return v[i] > bound; }
};
// v at point (i, j, k) of a box nx x ny, stored x fastest.
struct ValueAtPoint {
  const float* v;
  int nx, ny;
  DP_HD float operator()(int i, int j, int k) const { return v[i + nx * (j + static_cast<std::size_t>(ny) * k)]; }
};
// Pass s: out[i] = in[i] + s, reading the previous pass's output of the
// neighbour i + 1, so a missing barrier between passes shows.
struct ShiftingPasses {
  std::size_t n;
  float* a;
  float* b;
  DP_HD void operator()(int s, std::size_t i) const {
    const float* in = s % 2 ? b : a;
    float* out = s % 2 ? a : b;
    out[i] = in[(i + 1) % n] + static_cast<float>(s);
  }
};

std::vector<float> random_values(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::vector<float> v(n);
  for (float& x : v) x = u(rng);
  return v;
}

TEST_F(CudaBackend, SumsAreBitwiseThoseOfTheCpu) {
  CudaExec gpu(0);
  CpuExec cpu(3);
  for (std::size_t n : {std::size_t{1}, std::size_t{31}, std::size_t{1024}, std::size_t{1025}, std::size_t{262144 + 77},
                        std::size_t{1024 * 1024 + 5000}}) {  // three levels of block sums
    SCOPED_TRACE(n);
    const std::vector<float> host = random_values(n, static_cast<unsigned>(n));
    CudaExec::Buffer<float> device;
    CudaExec::upload(device, host);
    const double on_gpu = gpu.sum(n, ValueOf{CudaExec::ptr(device)});
    const double on_cpu = cpu.sum(n, ValueOf{host.data()});
    EXPECT_EQ(on_gpu, on_cpu);
    // The same sum left on the device, in the same order.
    CudaExec::Buffer<double> scratch(sum_scratch_count(n) + 1);
    gpu.sum_into(n, ValueOf{CudaExec::ptr(device)}, CudaExec::ptr(scratch) + 1, CudaExec::ptr(scratch));
    EXPECT_EQ(CudaExec::download_one(scratch, 0), on_cpu);
    long double reference = 0;
    for (float x : host) reference += x;
    EXPECT_NEAR(on_cpu, static_cast<double>(reference), 1e-12 * static_cast<double>(n));
  }
  EXPECT_EQ(gpu.sum(0, ValueOf{nullptr}), 0.0);
}

// After a sum into s[0]: s[1] = s[0], and one more call counted in s[2].
struct CopyAndCount {
  double* s;
  DP_HD void operator()(std::size_t) const {
    s[1] = s[0];
    s[2] += 1.0;
  }
};

// sum_into's last warp adds the levels after the first and runs `then`;
// the count of finished warps must be back to zero for the next sum, also
// when the sums are replayed from a recorded graph.
TEST_F(CudaBackend, SumIntoFinishesInItsLaunchAndCanBeReplayed) {
  CudaExec gpu(0);
  CpuExec cpu(2);
  for (std::size_t n : {std::size_t{1000}, std::size_t{262144 + 77}, std::size_t{1024 * 1024 + 5000}}) {  // 1, 2, 3 levels
    SCOPED_TRACE(n);
    const std::vector<float> host = random_values(n, static_cast<unsigned>(n) + 1);
    CudaExec::Buffer<float> device;
    CudaExec::upload(device, host);
    const double expected = cpu.sum(n, ValueOf{host.data()});
    CudaExec::Buffer<double> scratch(sum_scratch_count(n)), result(3, 0.0);
    const CopyAndCount then{CudaExec::ptr(result)};
    CudaExec::Recording twice;
    for (int replay = 0; replay < 3; ++replay)
      gpu.replay(twice, [&] {
        for (int k = 0; k < 2; ++k) gpu.sum_into(n, ValueOf{CudaExec::ptr(device)}, CudaExec::ptr(scratch), CudaExec::ptr(result), then);
      });
    gpu.synchronize();
    const std::vector<double> r = CudaExec::download(result);
    EXPECT_EQ(r[0], expected);
    EXPECT_EQ(r[1], expected);
    EXPECT_EQ(r[2], 6.0);
  }
}

TEST_F(CudaBackend, MaxAndFirstMatchTheCpu) {
  CudaExec gpu(0);
  CpuExec cpu(2);
  const std::size_t n = 300000;
  std::vector<float> host = random_values(n, 7);
  host[123457] = 5.0f;
  host[250001] = 4.0f;
  CudaExec::Buffer<float> device;
  CudaExec::upload(device, host);
  EXPECT_EQ(gpu.max(n, ValueOf{CudaExec::ptr(device)}, -1e30f), 5.0f);
  EXPECT_EQ(cpu.max(n, ValueOf{host.data()}, -1e30f), 5.0f);
  EXPECT_EQ(gpu.find_first(n, IsAbove{CudaExec::ptr(device), 3.0f}), std::size_t{123457});
  EXPECT_EQ(gpu.find_first(n, IsAbove{CudaExec::ptr(device), 4.5f}), std::size_t{123457});
  EXPECT_EQ(gpu.find_first(n, IsAbove{CudaExec::ptr(device), 6.0f}), n);
  EXPECT_EQ(gpu.max(0, ValueOf{nullptr}, -2.0f), -2.0f);
  // The same values as boxes 100 wide and 50 deep: max_3d runs by cells on
  // the GPU and by rows on the CPU. 40 layers hold index 123457 (5.0), not
  // 250001; 24 layers end before both.
  for (int layers : {60, 40, 24}) {
    SCOPED_TRACE(layers);
    const float expected = cpu.max(static_cast<std::size_t>(100 * 50 * layers), ValueOf{host.data()}, -1e30f);
    EXPECT_EQ(cpu.max_3d(100, 50, layers, ValueAtPoint{host.data(), 100, 50}, -1e30f), expected);
    EXPECT_EQ(gpu.max_3d(100, 50, layers, ValueAtPoint{CudaExec::ptr(device), 100, 50}, -1e30f), expected);
  }
  EXPECT_EQ(gpu.max_3d(100, 50, 0, ValueAtPoint{nullptr, 100, 50}, -2.0f), -2.0f);
}

TEST_F(CudaBackend, SweepsSeeThePreviousPassEntire) {
  CudaExec gpu(0);
  CpuExec cpu(2);
  for (std::size_t n : {std::size_t{64}, std::size_t{343}, std::size_t{5000}}) {  // one block, and one launch per pass
    SCOPED_TRACE(n);
    const std::vector<float> start = random_values(n, 11);
    std::vector<float> a = start, b(n);
    CudaExec::Buffer<float> da, db(n);
    CudaExec::upload(da, start);
    cpu.parallel_sweeps(n, 9, ShiftingPasses{n, a.data(), b.data()});
    gpu.parallel_sweeps(n, 9, ShiftingPasses{n, CudaExec::ptr(da), CudaExec::ptr(db)});
    EXPECT_EQ(CudaExec::download(db), b);  // 9 passes: the last wrote b
    // Independently: after 9 passes element i holds start[(i + 9) % n] + 0 + 1 + ... + 8.
    for (std::size_t i = 0; i < n; i += n / 7) EXPECT_NEAR(b[i], start[(i + 9) % n] + 36.0f, 1e-5f);
  }
}

}  // namespace
}  // namespace dp
