// The CPU backend gives bit-identical results for any thread count
// (DESIGN §3: gather, no floating-point atomics, fixed summation order).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <string>

#include <omp.h>

#include "backend/counting_sort.h"
#include "backend/cpu_exec.h"
#include "sph/particle_grid.h"
#include "sph/density.h"
#include "test_scenes.h"

namespace dp {
namespace {

struct KernelResults {
  std::vector<std::uint32_t> sorted_keys, order, scanned;
  std::vector<float> density;
  double sum = 0;
  std::size_t first = 0;
  float max = 0;
};

std::vector<Vec3> random_points(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 0.3f);
  std::vector<Vec3> p(n);
  for (auto& x : p) x = Vec3{u(rng), u(rng), u(rng)};
  return p;
}

KernelResults run_kernels(int threads) {
  CpuExec exec(threads);
  KernelResults r;
  std::vector<Vec3> points = random_points(20000, 7);

  ParticleGrid<CpuExec> pg;
  pg.grid = UniformGrid{Vec3{0, 0, 0}, 0.02f, 16, 16, 16};
  CpuExec::Buffer<Vec3> pos = points, sorted(points.size());
  pg.sort(exec, pos);
  exec.parallel_for(points.size(), Gather<Vec3>{pg.order.data(), pos.data(), sorted.data()});
  pg.find_ranges(exec);
  r.sorted_keys = pg.key;
  r.order = pg.order;

  CpuExec::Buffer<std::uint32_t> counts(pg.grid.cell_count()), offsets;
  exec.parallel_for(counts.size(), [&](std::size_t c) { counts[c] = pg.cell_begin[c + 1] - pg.cell_begin[c]; });
  exec.exclusive_scan(counts, offsets);
  r.scanned = offsets;

  CpuExec::Buffer<float> density(points.size()), no_volume;
  CpuExec::Buffer<MassUnits> units(points.size());
  for (std::size_t i = 0; i < units.size(); ++i) units[i] = kFullParticleUnits - static_cast<MassUnits>(i % 97);
  GridView liquid = pg.view(sorted);
  ParticleGrid<CpuExec> empty;
  empty.grid = pg.grid;
  CpuExec::Buffer<Vec3> none;
  empty.sort(exec, none);
  empty.find_ranges(exec);
  DensityAt density_at{liquid, empty.view(none), units.data(), no_volume.data(),
                       CubicSplineKernel::with_support(0.02f), 0.001f, 1000.0f};
  exec.parallel_for(points.size(), [&](std::size_t i) { density[i] = density_at(sorted[i]); });
  r.density = density;
  r.sum = exec.sum(density.size(), [&](std::size_t i) { return density[i] * 1.0001f; });
  r.first = exec.find_first(density.size(), [&](std::size_t i) { return density[i] > 0.2f; });
  r.max = exec.max(density.size(), [&](std::size_t i) { return density[i]; }, 0.0f);
  return r;
}

template <class T>
bool bitwise_equal(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

TEST(CpuBackend, KernelsAreBitIdenticalForAnyThreadCount) {
  KernelResults one = run_kernels(1);
  for (int threads : {2, 3, 8}) {
    KernelResults many = run_kernels(threads);
    EXPECT_TRUE(bitwise_equal(one.sorted_keys, many.sorted_keys)) << threads << " threads";
    EXPECT_TRUE(bitwise_equal(one.order, many.order)) << threads << " threads";
    EXPECT_TRUE(bitwise_equal(one.scanned, many.scanned)) << threads << " threads";
    EXPECT_TRUE(bitwise_equal(one.density, many.density)) << threads << " threads";
    EXPECT_EQ(std::memcmp(&one.sum, &many.sum, sizeof(double)), 0) << threads << " threads";
    EXPECT_EQ(one.first, many.first);
    EXPECT_EQ(one.max, many.max);
  }
}

// max_3d over a box, by rows, against the largest over a flat loop; a box
// narrower than the stored rows shows a row read past its end.
TEST(CpuBackend, BoxMaximumIsTheLargestOverTheBox) {
  const int stored = 9, nx = 7, ny = 5, nz = 4;
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  std::vector<float> v(static_cast<std::size_t>(stored) * ny * nz);
  for (float& x : v) x = u(rng);
  for (int j = 0; j < ny; ++j)
    for (int k = 0; k < nz; ++k) v[nx + stored * (j + ny * k)] = 2.0f;  // beyond the box
  float expected = -1e30f;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) expected = std::max(expected, v[i + stored * (j + ny * k)]);
  const auto at = [&](int i, int j, int k) { return v[i + stored * (j + ny * k)]; };
  for (int threads : {1, 2, 3}) EXPECT_EQ(CpuExec(threads).max_3d(nx, ny, nz, at, -1e30f), expected);
  EXPECT_EQ(CpuExec(2).max_3d(nx, ny, 0, at, -5.0f), -5.0f);
  EXPECT_EQ(CpuExec(2).max_3d(0, ny, nz, at, -5.0f), -5.0f);
}

TEST(CpuBackend, SortIsStableAndScanIsExclusive) {
  CpuExec exec(2);
  CpuExec::Buffer<std::uint32_t> keys{3, 1, 2, 1, 3, 0}, values{0, 1, 2, 3, 4, 5}, out;
  exec.sort_by_key(keys, values);
  EXPECT_EQ(keys, (std::vector<std::uint32_t>{0, 1, 1, 2, 3, 3}));
  EXPECT_EQ(values, (std::vector<std::uint32_t>{5, 1, 3, 2, 0, 4}));
  exec.exclusive_scan(keys, out);
  EXPECT_EQ(out, (std::vector<std::uint32_t>{0, 0, 1, 2, 4, 7}));
}

// The CPU sorts the cells' pairs by counting (CellPairIndex::build). Its
// order, runs and cells must be the standard library's stable sort, for
// any number of shares: keys clustered as a liquid's stencils are, keys at
// 0 and at the bound's last cell, one key, none, and a share count above
// the thread count. The reused counts must start from zero every time.
TEST(CpuBackend, CountingSortIsTheStableSortWithItsRuns) {
  std::mt19937 rng(23);
  const std::uint32_t bound = 64 * 64 * 64;
  std::vector<std::vector<std::uint32_t>> inputs = {{}, {bound - 1}, {5, 5, 5}, {0, bound - 1, 0, 7, bound - 1}};
  std::normal_distribution<float> cluster(30000.0f, 800.0f);
  std::uniform_int_distribution<std::uint32_t> anywhere(0, bound - 1);
  for (std::size_t n : {1000u, 150000u}) {
    std::vector<std::uint32_t> k(n);
    for (std::size_t q = 0; q < n; ++q) k[q] = q % 9 == 0 ? anywhere(rng) : static_cast<std::uint32_t>(std::max(0.0f, cluster(rng)));
    inputs.push_back(k);
  }
  CountingSort sort;  // one sorter for every input, as a CellPairIndex keeps its own
  for (const std::vector<std::uint32_t>& key : inputs)
    for (int shares : {1, 2, 3, 7}) {
      const std::size_t n = key.size();
      std::vector<std::uint32_t> expected_order(n);
      for (std::size_t q = 0; q < n; ++q) expected_order[q] = static_cast<std::uint32_t>(q);
      std::stable_sort(expected_order.begin(), expected_order.end(), [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
      std::vector<std::uint32_t> expected_key, expected_run_key, expected_run_begin;
      for (std::size_t q = 0; q < n; ++q) {
        expected_key.push_back(key[expected_order[q]]);
        if (q == 0 || expected_key[q] != expected_key[q - 1]) {
          expected_run_key.push_back(expected_key[q]);
          expected_run_begin.push_back(static_cast<std::uint32_t>(q));
        }
      }
      expected_run_begin.push_back(static_cast<std::uint32_t>(n));
      std::vector<std::uint32_t> sorted(n), order(n), run_key, run_begin;
      sort.sort(shares, key.data(), n, bound, sorted.data(), order.data(), run_key, run_begin);
      ASSERT_EQ(order, expected_order) << n << " keys, " << shares << " shares";
      ASSERT_EQ(sorted, expected_key) << n << " keys, " << shares << " shares";
      ASSERT_EQ(run_key, expected_run_key) << n << " keys, " << shares << " shares";
      ASSERT_EQ(run_begin, expected_run_begin) << n << " keys, " << shares << " shares";
    }
}

// parallel_for_by_work: every element once, whatever the work, and each
// thread's contiguous share within one element of an equal part of it.
TEST(CpuBackend, WorkSharesVisitEveryElementOnceAndHoldEqualWork) {
  std::mt19937 rng(29);
  std::vector<std::vector<std::size_t>> works = {{}, {5000}, std::vector<std::size_t>(3000, 1), std::vector<std::size_t>(100, 0)};
  std::vector<std::size_t> head(2000, 0), tail(2000, 0), random(5000);
  for (std::size_t i = 0; i < 20; ++i) head[i] = 4000;                 // heavy first elements, then none
  for (std::size_t i = 1980; i < 2000; ++i) tail[i] = 4000;            // none, then heavy ones
  for (std::size_t& w : random) w = rng() % 7 == 0 ? rng() % 3000 : rng() % 4;
  works.insert(works.end(), {head, tail, random});
  for (const std::vector<std::size_t>& work : works) {
    std::vector<std::size_t> before(work.size() + 1, 0);
    for (std::size_t i = 0; i < work.size(); ++i) before[i + 1] = before[i] + work[i];
    const std::size_t largest = work.empty() ? 0 : *std::max_element(work.begin(), work.end());
    for (int threads : {1, 2, 3, 7}) {
      CpuExec exec(threads);
      std::vector<int> visits(work.size(), 0), thread(work.size(), -1);
      exec.parallel_for_by_work(work.size(), [&](std::size_t i) { return before[i]; }, [&](std::size_t i) {
        ++visits[i];
        thread[i] = omp_get_thread_num();
      });
      const std::string what = std::to_string(work.size()) + " elements, work " + std::to_string(before.back()) + ", " +
                               std::to_string(threads) + " threads";
      for (std::size_t i = 0; i < work.size(); ++i) ASSERT_EQ(visits[i], 1) << "element " << i << ", " << what;
      std::vector<std::size_t> share_work(threads, 0);
      for (std::size_t i = 0; i < work.size(); ++i) {
        if (i > 0) ASSERT_GE(thread[i], thread[i - 1]) << "shares are contiguous, " << what;
        share_work[static_cast<std::size_t>(thread[i])] += work[i];
      }
      if (before.back() < CpuExec::kSerialBelow) continue;  // on the calling thread
      for (int t = 0; t < threads; ++t)
        EXPECT_LE(share_work[t], before.back() / threads + largest) << "thread " << t << ", " << what;
    }
  }
}

TEST(CpuBackend, BlockedSumMatchesLongDoubleReference) {
  CpuExec exec(2);
  std::vector<float> v = {};
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (int i = 0; i < 100000; ++i) v.push_back(u(rng));
  long double reference = 0;
  for (float x : v) reference += x;
  double s = exec.sum(v.size(), [&](std::size_t i) { return v[i]; });
  EXPECT_NEAR(s, static_cast<double>(reference), 1e-9);
}

// The order blocked_sum.h defines, written out as the GPU walks it: per
// block of 1024, lane l adds elements l, l + 32, ... in turn, the lanes
// fold as a tree (l += l + 16, then + 8, ... + 1), and the block sums are
// summed the same way until one value is left.
double sum_in_warp_order(std::vector<double> level) {
  while (level.size() > 1) {
    std::vector<double> next;
    for (std::size_t begin = 0; begin < level.size(); begin += 1024) {
      const std::size_t end = std::min(begin + 1024, level.size());
      double lane[32];
      for (std::size_t l = 0; l < 32; ++l) {
        lane[l] = 0.0;
        for (std::size_t i = begin + l; i < end; i += 32) lane[l] += level[i];
      }
      for (std::size_t offset = 16; offset > 0; offset /= 2)
        for (std::size_t l = 0; l < offset; ++l) lane[l] += lane[l + offset];
      next.push_back(lane[0]);
    }
    level.swap(next);
  }
  return level.empty() ? 0.0 : level[0];
}

// The CPU walks each block contiguously (lane = i mod 32) and must still
// add in exactly that order, tails and several levels included: the CUDA
// backend's sums are compared with it bit for bit.
TEST(CpuBackend, BlockedSumAddsInTheWarpOrderBitForBit) {
  CpuExec exec(2);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t n : {std::size_t{1}, std::size_t{31}, std::size_t{1000}, std::size_t{1024 + 33},
                        std::size_t{1024 * 1024 + 5000}}) {
    std::vector<double> v(n);
    for (double& x : v) x = u(rng) * std::exp(20.0 * u(rng));  // wide range: the order shows in the rounding
    const double s = exec.sum(n, [&](std::size_t i) { return v[i]; });
    const double reference = sum_in_warp_order(v);
    EXPECT_EQ(std::memcmp(&s, &reference, sizeof s), 0) << "n = " << n << ": " << s << " vs " << reference;
  }
}

void expect_steps_bit_identical_for_any_thread_count(const SimulationSetup& setup) {
  auto run = [&](int threads) {
    auto sim = make_simulation(ExecutionConfig{Device::Cpu, threads}, setup);
    for (int i = 0; i < 40; ++i) sim->step();
    return sim->particles();
  };
  ParticleSnapshot one = run(1), two = run(2), five = run(5);
  ASSERT_EQ(one.size(), setup.liquid_position.size());
  EXPECT_TRUE(bitwise_equal(one.position, two.position));
  EXPECT_TRUE(bitwise_equal(one.velocity, two.velocity));
  EXPECT_TRUE(bitwise_equal(one.density, two.density));
  EXPECT_TRUE(bitwise_equal(one.id, two.id));
  EXPECT_TRUE(bitwise_equal(one.position, five.position));
  EXPECT_TRUE(bitwise_equal(one.velocity, five.velocity));
  EXPECT_TRUE(bitwise_equal(one.pressure, five.pressure));
}

TEST(Simulation, CpuStepsAreBitIdenticalForAnyThreadCount) {
  expect_steps_bit_identical_for_any_thread_count(test::block_over_plate(10, 8, 10));
}

TEST(Simulation, DfsphCpuStepsAreBitIdenticalForAnyThreadCount) {
  SimulationSetup setup = test::block_over_plate(10, 8, 10);
  setup.pressure.method = PressureSolverMethod::Dfsph;
  expect_steps_bit_identical_for_any_thread_count(setup);
}

}  // namespace
}  // namespace dp
