// The neighbour grid's cell ranges (Green 2009), against the standard
// library's equal_range over the sorted keys and against a scan of every
// particle; on one thread, on two, and through the per-cell search the CUDA
// backend runs. Then what the CPU computes from the grid in its own way:
// the neighbour lists (against a scan of every point) and the pair sums
// over them (density, XSPH, Akinci's surface tension and adhesion, Morris's
// viscosity), each against the one-particle-at-a-time code the GPU runs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "backend/cpu_exec.h"
#include "sph/density.h"
#include "sph/kernel_cubic_spline.h"
#include "sph/neighbor_list.h"
#include "sph/particle_grid.h"
#include "sph/surface_tension_akinci2013.h"
#include "sph/viscosity_morris1997.h"
#include "sph/viscosity_xsph.h"

namespace dp {
namespace {

// Clustered points: two dense blobs and a sparse scatter, so that most
// cells are empty and the gaps between occupied cells are long (the case
// of a small liquid body in a large domain).
std::vector<Vec3> clustered_points(unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> blob(0.0f, 0.03f);
  std::uniform_real_distribution<float> anywhere(-0.1f, 1.1f);  // some fall outside and clamp
  std::vector<Vec3> p;
  for (int n = 0; n < 6000; ++n) p.push_back(Vec3{0.2f + blob(rng), 0.3f + blob(rng), 0.25f + blob(rng)});
  for (int n = 0; n < 3000; ++n) p.push_back(Vec3{0.8f + blob(rng), 0.7f + blob(rng), 0.9f + blob(rng)});
  for (int n = 0; n < 200; ++n) p.push_back(Vec3{anywhere(rng), anywhere(rng), anywhere(rng)});
  return p;
}

struct Built {
  ParticleGrid<CpuExec> grid;
  std::vector<Vec3> sorted;
};

Built build(int threads, const std::vector<Vec3>& points, const UniformGrid& g) {
  CpuExec exec(threads);
  Built b;
  b.grid.grid = g;
  b.grid.sort(exec, points);
  b.sorted.resize(points.size());
  exec.parallel_for(points.size(), Gather<Vec3>{b.grid.order.data(), points.data(), b.sorted.data()});
  b.grid.find_ranges(exec);
  return b;
}

const UniformGrid kGrid{Vec3{0, 0, 0}, 0.02f, 50, 50, 50};

TEST(UniformGrid, EveryCellsRangeIsTheEqualRangeOfItsKey) {
  const std::vector<Vec3> points = clustered_points(3);
  for (int threads : {1, 2}) {
    const Built b = build(threads, points, kGrid);
    const std::vector<std::uint32_t>& key = b.grid.key;
    ASSERT_TRUE(std::is_sorted(key.begin(), key.end()));
    ASSERT_EQ(b.grid.cell_begin.size(), kGrid.cell_count() + std::size_t{1});
    for (std::uint32_t c = 0; c < kGrid.cell_count(); ++c) {
      const auto [first, last] = std::equal_range(key.begin(), key.end(), c);
      ASSERT_EQ(b.grid.cell_begin[c], first - key.begin()) << "cell " << c << ", " << threads << " threads";
      ASSERT_EQ(b.grid.cell_begin[c + 1], last - key.begin()) << "cell " << c << ", " << threads << " threads";
    }
  }
}

TEST(UniformGrid, PerCellSearchEqualsTheRangeWalk) {
  // The CUDA backend calls CellBegins per cell; the CPU one hands it ranges.
  const std::vector<Vec3> points = clustered_points(5);
  const Built b = build(2, points, kGrid);
  std::vector<std::uint32_t> per_cell(b.grid.cell_begin.size());
  const CellBegins begins{b.grid.key.data(), static_cast<std::uint32_t>(b.grid.key.size()), per_cell.data()};
  for (std::size_t c = 0; c < per_cell.size(); ++c) begins(c);
  EXPECT_EQ(per_cell, b.grid.cell_begin);
}

TEST(UniformGrid, NeighbourWalkVisitsExactlyTheParticlesOfThe27Cells) {
  const std::vector<Vec3> points = clustered_points(7);
  const Built b = build(2, points, kGrid);
  const GridView view = b.grid.view(b.sorted);
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> anywhere(-0.05f, 1.05f);
  std::vector<Vec3> queries(points.begin(), points.begin() + 100);
  for (int n = 0; n < 100; ++n) queries.push_back(Vec3{anywhere(rng), anywhere(rng), anywhere(rng)});
  for (const Vec3& q : queries) {
    int qi, qj, qk;
    kGrid.cell_of(q, qi, qj, qk);
    std::vector<std::uint32_t> expected;
    for (std::uint32_t n = 0; n < b.sorted.size(); ++n) {
      int i, j, k;
      kGrid.cell_of(b.sorted[n], i, j, k);
      if (std::abs(i - qi) <= 1 && std::abs(j - qj) <= 1 && std::abs(k - qk) <= 1) expected.push_back(n);
    }
    std::vector<std::uint32_t> found;
    view.for_each_near(q, [&](std::uint32_t n) { found.push_back(n); });
    std::sort(found.begin(), found.end());
    ASSERT_EQ(found, expected) << "query (" << q.x << ", " << q.y << ", " << q.z << ")";
  }
}

// RecordWetting visits only the cells within its contact radius. Every
// particle closer than the radius must be among them, and the visit keeps
// the walk's ascending order; below the cell size it visits no cell outside
// the 27. Besides clustered points, each radius r gets pairs that test the
// box's edges: a query 0.9925 r past a cell face along each axis and each
// direction, and a particle 0.995 r from it across that face, so that a box
// even 1 % too small misses the particle's cell.
TEST(UniformGrid, RunsWithinARadiusHoldEveryParticleCloserThanIt) {
  const float h = kGrid.cell_size;
  std::mt19937 rng(13);
  std::uniform_real_distribution<float> anywhere(-0.05f, 1.05f);
  for (float radius : {0.3f * h, 0.707f * h, 0.999f * h, h, 1.6f * h}) {
    std::vector<Vec3> points = clustered_points(9);
    std::vector<Vec3> queries(points.begin(), points.begin() + 100);
    for (int n = 0; n < 100; ++n) queries.push_back(Vec3{anywhere(rng), anywhere(rng), anywhere(rng)});
    for (int n = 0; n < 20; ++n) {
      const Vec3 face = h * Vec3{float(10 + n % 7), float(12 + n % 5), float(15 + n % 3)};
      for (Vec3 axis : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}})
        for (float side : {1.0f, -1.0f}) {
          const Vec3 q = face + (side * 0.9925f * radius) * axis;
          queries.push_back(q);
          points.push_back(q - (side * 0.995f * radius) * axis);
        }
    }
    const Built b = build(2, points, kGrid);
    const GridView view = b.grid.view(b.sorted);
    for (const Vec3& q : queries) {
      std::vector<std::uint32_t> within, near;
      view.for_each_run_within(q, radius, [&](std::uint32_t first, std::uint32_t end) {
        for (std::uint32_t n = first; n < end; ++n) within.push_back(n);
      });
      view.for_each_near(q, [&](std::uint32_t n) { near.push_back(n); });
      ASSERT_TRUE(std::is_sorted(within.begin(), within.end()));
      for (std::uint32_t n = 0; n < b.sorted.size(); ++n) {
        if (!(length_squared(b.sorted[n] - q) < radius * radius)) continue;
        ASSERT_TRUE(std::binary_search(within.begin(), within.end(), n))
            << "particle " << n << " at " << length(b.sorted[n] - q) / h << " h from (" << q.x << ", " << q.y << ", " << q.z
            << "), radius " << radius / h << " h";
      }
      if (radius < h) ASSERT_TRUE(std::includes(near.begin(), near.end(), within.begin(), within.end()));
    }
  }
  const Built b = build(2, clustered_points(9), kGrid);
  std::size_t visited = 0;
  b.grid.view(b.sorted).for_each_run_within(Vec3{0.2f, 0.3f, 0.25f}, -1.0f,
                                             [&](std::uint32_t first, std::uint32_t end) { visited += end - first; });
  EXPECT_EQ(visited, 0u);
}

// One grid rebuilt for a sequence of particle sets, as a simulation does
// every step: the CPU backend rewrites only the cells whose begin can have
// changed, so every entry is checked after each set against a search of
// that set's keys alone. The sets move the lowest and highest keys down
// and up, change the count, and empty the grid.
TEST(UniformGrid, RebuiltGridsRangesMatchEachNewSetOfKeys) {
  const std::vector<Vec3> base = clustered_points(13);
  const auto moved = [&](Vec3 by, std::size_t count) {
    std::vector<Vec3> p(base.begin(), base.begin() + count);
    for (Vec3& x : p) x = x + by;
    return p;
  };
  const std::vector<std::vector<Vec3>> sets = {
      moved({0, 0, 0}, 6000),        moved({0, 0, 0.1f}, 6000),  moved({0, 0, -0.15f}, 6000),
      moved({0.02f, 0, 0}, 6000),    moved({0, 0, 0.3f}, 5000),  moved({0, 0, 0.3f}, 5000),
      {},                            moved({0, 0.1f, 0}, 9200),  moved({0, -0.1f, 0.2f}, 9200),
      moved({0, -0.1f, 0.2f}, 9199), {Vec3{0.5f, 0.5f, 0.5f}},    moved({0, 0, 0}, 6000)};
  for (int threads : {1, 2}) {
    CpuExec exec(threads);
    ParticleGrid<CpuExec> grid;
    grid.grid = kGrid;
    for (std::size_t s = 0; s < sets.size(); ++s) {
      grid.sort(exec, sets[s]);
      grid.find_ranges(exec);
      const std::vector<std::uint32_t>& key = grid.key;
      ASSERT_EQ(grid.cell_begin.size(), kGrid.cell_count() + std::size_t{1});
      for (std::uint32_t c = 0; c <= kGrid.cell_count(); ++c)
        ASSERT_EQ(grid.cell_begin[c], std::lower_bound(key.begin(), key.end(), c) - key.begin())
            << "cell " << c << " after set " << s << ", " << threads << " threads";
    }
  }
}

// The CPU fills its lists in one walk, chunk by chunk (FillListChunks),
// without a branch per candidate; the GPU counts, scans and fills one list
// per thread (CountNeighbors, FillNeighbors::operator()). Both must give
// every particle the points within the radius, ascending as the grid
// stores them, with the same gradient factors bit for bit, for any thread
// count, also for lists longer than the chunks keep locally (the blobs'
// cores hold several hundred points within one cell size).
TEST(NeighbourLists, ChunkFillIsTheScanOfEveryPointAndTheOneAtATimeFill) {
  std::mt19937 rng(17);
  std::normal_distribution<float> blob(0.0f, 0.03f);
  std::uniform_real_distribution<float> inside(0.05f, 0.95f);
  std::vector<Vec3> points;
  for (int n = 0; n < 4000; ++n) points.push_back(Vec3{0.3f + blob(rng), 0.4f + blob(rng), 0.5f + blob(rng)});
  for (int n = 0; n < 2000; ++n) points.push_back(Vec3{inside(rng), inside(rng), inside(rng)});
  const Built b = build(2, points, kGrid);
  const GridView view = b.grid.view(b.sorted);
  const CubicSplineKernel kernel = CubicSplineKernel::with_support(kGrid.cell_size);
  const std::size_t n = b.sorted.size();
  ASSERT_GT(n, 2 * ListChunks::kChunk);  // several chunks, one of them partial

  // The GPU's way, one particle at a time.
  const float r2 = kernel.h * kernel.h;
  std::vector<std::uint32_t> count(n + 1, 0), offset(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) CountNeighbors{b.sorted.data(), view, r2, count.data()}(i);
  for (std::size_t i = 0; i < n; ++i) offset[i + 1] = offset[i] + count[i];
  std::vector<std::uint32_t> one_at_a_time(offset[n]);
  std::vector<float> factor_one_at_a_time(offset[n]);
  const FillNeighbors fill{b.sorted.data(), view, r2, offset.data(), one_at_a_time.data(), kernel, factor_one_at_a_time.data()};
  std::size_t long_lists = 0;
  for (std::size_t i = 0; i < n; ++i) {
    fill(i);
    std::vector<std::uint32_t> scan;
    for (std::uint32_t j = 0; j < n; ++j)
      if (length_squared(b.sorted[i] - b.sorted[j]) < r2) scan.push_back(j);
    const std::vector<std::uint32_t> listed(one_at_a_time.begin() + offset[i], one_at_a_time.begin() + offset[i + 1]);
    ASSERT_EQ(listed, scan) << "particle " << i;
    long_lists += listed.size() > FillListChunks::kMaxListed ? 1 : 0;
  }
  EXPECT_GT(long_lists, 100u);  // the chunks' second walk ran

  for (int threads : {1, 2, 3}) {
    CpuExec exec(threads);
    NeighborListBuffers<CpuExec> lists;
    lists.build_with_gradients(exec, b.sorted, view, kernel);
    EXPECT_EQ(lists.offset, offset) << threads << " threads";
    EXPECT_EQ(lists.index, one_at_a_time) << threads << " threads";
    ASSERT_EQ(lists.gradient_factor.size(), factor_one_at_a_time.size());
    EXPECT_EQ(0, std::memcmp(lists.gradient_factor.data(), factor_one_at_a_time.data(), factor_one_at_a_time.size() * sizeof(float)))
        << threads << " threads";
    NeighborListBuffers<CpuExec> plain;  // without gradient factors
    plain.build(exec, b.sorted, view, kernel.h);
    EXPECT_EQ(plain.index, one_at_a_time) << threads << " threads";
  }
}

// The CPU's densities over the lists (ListedDensity::split_sum: terms
// first, then their sum) against the one-loop sum the GPU runs, bit for
// bit: at the lists' own positions, and at moved positions (as PCISPH's
// predicted ones) where some listed pairs have left the support and must
// add nothing, with adaptive masses and boundary particles, and for lists
// longer than split_sum keeps locally.
TEST(NeighbourLists, SplitDensitySumIsTheOneLoopSumBitForBit) {
  std::mt19937 rng(23);
  std::normal_distribution<float> blob(0.0f, 0.03f);
  std::uniform_real_distribution<float> inside(0.05f, 0.95f), jitter(-0.004f, 0.004f);
  std::uniform_int_distribution<std::uint32_t> units(1, kFullParticleUnits);
  std::vector<Vec3> points, boundary;
  for (int n = 0; n < 4000; ++n) points.push_back(Vec3{0.3f + blob(rng), 0.4f + blob(rng), 0.5f + blob(rng)});
  for (int n = 0; n < 3000; ++n) points.push_back(Vec3{inside(rng), inside(rng), inside(rng)});
  for (int n = 0; n < 3000; ++n) boundary.push_back(Vec3{inside(rng), 0.35f + 0.01f * inside(rng), inside(rng)});
  const Built liquid = build(2, points, kGrid), rigid = build(2, boundary, kGrid);
  const CubicSplineKernel kernel = CubicSplineKernel::with_support(kGrid.cell_size);
  CpuExec exec(2);
  NeighborListBuffers<CpuExec> liquid_lists, rigid_lists;
  const NeighborList ll = liquid_lists.build(exec, liquid.sorted, liquid.grid.view(liquid.sorted), kernel.h);
  const NeighborList lr = rigid_lists.build(exec, liquid.sorted, rigid.grid.view(rigid.sorted), kernel.h);
  std::vector<MassUnits> mass_units(points.size());
  for (MassUnits& u : mass_units) u = units(rng);
  std::vector<float> volume(boundary.size());
  for (float& v : volume) v = 1e-6f * (0.5f + inside(rng));
  std::vector<Vec3> moved(liquid.sorted);
  for (Vec3& x : moved) x = x + Vec3{jitter(rng), jitter(rng), jitter(rng)};
  std::size_t long_lists = 0, left_support = 0;
  for (const std::vector<Vec3>* at : std::initializer_list<const std::vector<Vec3>*>{&liquid.sorted, &moved}) {
    const ListedDensity density{ll, lr, at->data(), rigid.sorted.data(), mass_units.data(), volume.data(), kernel, 0.008f, 1000.0f};
    for (std::size_t i = 0; i < at->size(); ++i) {
      const float one_loop = density(i), split = density.split_sum(i);
      ASSERT_EQ(bits_of(split), bits_of(one_loop)) << "particle " << i;
      long_lists += fits_in_list_order(ll, i) ? 0 : 1;
      for (std::uint32_t k = ll.offset[i]; k < ll.offset[i + 1]; ++k)
        left_support += length_squared((*at)[i] - (*at)[ll.index[k]]) >= kernel.h * kernel.h ? 1 : 0;
    }
  }
  EXPECT_GT(long_lists, 100u);    // the fallback ran
  EXPECT_GT(left_support, 1000u);  // zeroed terms were summed
}

// What the particle step's pair sums read: a liquid cloud (a dense blob
// with lists longer than the split sums keep locally, a scatter, and one
// particle doubled, so one pair is coincident) above a sheet of boundary
// particles, the step's lists with their gradient factors, and random
// masses, densities, velocities, normals, volumes and adhesions.
struct PairSumScene {
  Built liquid, rigid;
  CubicSplineKernel kernel = CubicSplineKernel::with_support(kGrid.cell_size);
  NeighborListBuffers<CpuExec> liquid_lists, rigid_lists;
  ListedPairs liquid_pairs, rigid_pairs;
  std::vector<MassUnits> units;
  std::vector<float> density, volume, adhesion;
  std::vector<float> liquid_mass, liquid_volume;  // of particles of 0.008 kg (ParticleMass, ParticleVolume)
  std::vector<Vec3> velocity, normal, moved;

  explicit PairSumScene(unsigned seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<float> blob(0.0f, 0.03f);
    std::uniform_real_distribution<float> inside(0.05f, 0.95f), unit(0.0f, 1.0f), jitter(-0.004f, 0.004f);
    std::vector<Vec3> points, boundary;
    for (int n = 0; n < 4000; ++n) points.push_back(Vec3{0.3f + blob(rng), 0.4f + blob(rng), 0.5f + blob(rng)});
    for (int n = 0; n < 3000; ++n) points.push_back(Vec3{inside(rng), inside(rng), inside(rng)});
    points.push_back(points[4500]);
    for (int n = 0; n < 3000; ++n) boundary.push_back(Vec3{inside(rng), 0.35f + 0.01f * inside(rng), inside(rng)});
    liquid = build(2, points, kGrid);
    rigid = build(2, boundary, kGrid);
    CpuExec exec(2);
    liquid_pairs = liquid_lists.build_with_gradients(exec, liquid.sorted, liquid.grid.view(liquid.sorted), kernel);
    rigid_pairs = rigid_lists.build_with_gradients(exec, liquid.sorted, rigid.grid.view(rigid.sorted), kernel);
    for (std::size_t i = 0; i < points.size(); ++i) {
      units.push_back(1 + static_cast<MassUnits>(unit(rng) * (kFullParticleUnits - 1)));
      density.push_back(900.0f + 200.0f * unit(rng));
      velocity.push_back(Vec3{unit(rng) - 0.5f, unit(rng) - 0.5f, unit(rng) - 0.5f});
      normal.push_back(Vec3{unit(rng) - 0.5f, unit(rng) - 0.5f, unit(rng) - 0.5f});
      moved.push_back(liquid.sorted[i] + Vec3{jitter(rng), jitter(rng), jitter(rng)});
    }
    for (std::size_t b = 0; b < boundary.size(); ++b) {
      volume.push_back(1e-6f * (0.5f + unit(rng)));
      adhesion.push_back(5.0f + 10.0f * unit(rng));
    }
    liquid_mass.resize(size());
    liquid_volume.resize(size());
    exec.parallel_for(size(), ParticleMass{units.data(), 0.008f, liquid_mass.data()});
    exec.parallel_for(size(), ParticleVolume{liquid_mass.data(), density.data(), liquid_volume.data()});
  }
  std::size_t size() const { return liquid.sorted.size(); }
  std::size_t long_lists() const {
    std::size_t count = 0;
    for (std::size_t i = 0; i < size(); ++i)
      count += fits_in_list_order(liquid_pairs.list, i) ? 0 : 1;
    return count;
  }
};

// Runs f's whole_range over every particle and f's operator() on each, into
// `out` as f writes it (from `start` where f adds to it), and compares bits.
template <class MakeFunctor>
void expect_whole_range_is_one_loop(const std::vector<Vec3>& start, const MakeFunctor& make) {
  std::vector<Vec3> split(start), one_loop(start);
  make(split.data()).whole_range(0, split.size());
  const auto f = make(one_loop.data());
  for (std::size_t i = 0; i < one_loop.size(); ++i) f(i);
  for (std::size_t i = 0; i < split.size(); ++i) {
    ASSERT_EQ(bits_of(split[i].x), bits_of(one_loop[i].x)) << "particle " << i;
    ASSERT_EQ(bits_of(split[i].y), bits_of(one_loop[i].y)) << "particle " << i;
    ASSERT_EQ(bits_of(split[i].z), bits_of(one_loop[i].z)) << "particle " << i;
  }
}

// XSPH reads the moved positions over the step's lists, so pairs that left
// the support must add nothing, as in the density test above.
TEST(NeighbourLists, SplitXsphIsTheOneLoopSumBitForBit) {
  const PairSumScene s(29);
  ASSERT_GT(s.long_lists(), 100u);
  expect_whole_range_is_one_loop(std::vector<Vec3>(s.size()), [&](Vec3* smoothed) {
    return ApplyXsph{s.liquid_pairs.list, s.rigid_pairs.list, s.moved.data(), s.rigid.sorted.data(), s.liquid_volume.data(),
                     s.volume.data(), s.velocity.data(), s.kernel, 0.01f, 0.1f, smoothed};
  });
}

TEST(NeighbourLists, SplitSurfaceTensionAndAdhesionAreTheOneLoopSumsBitForBit) {
  const PairSumScene s(31);
  const SurfaceTensionParameters p{s.kernel, 0.008f, 1000.0f, 2.0f};
  expect_whole_range_is_one_loop(std::vector<Vec3>(s.size()), [&](Vec3* acceleration) {
    return ComputeSurfaceTensionAcceleration{s.liquid.grid.view(s.liquid.sorted), s.rigid.grid.view(s.rigid.sorted), s.units.data(),
                                             s.density.data(), s.normal.data(), s.volume.data(), s.adhesion.data(), p, acceleration,
                                             s.liquid_pairs, s.rigid_pairs};
  });
}

// Morris adds to the acceleration it is given; both wall shears.
TEST(NeighbourLists, SplitMorrisViscosityIsTheOneLoopSumBitForBit) {
  const PairSumScene s(37);
  for (WallShear shear : {WallShear::NoSlip, WallShear::Spalding1961}) {
    expect_whole_range_is_one_loop(s.normal, [&](Vec3* acceleration) {
      return AddViscosityMorris1997{s.liquid.grid.view(s.liquid.sorted), s.rigid.grid.view(s.rigid.sorted), s.units.data(),
                                    s.density.data(), s.volume.data(), s.velocity.data(), s.kernel, 0.008f, 1e-6f, 0.9f,
                                    acceleration, s.liquid_pairs, s.rigid_pairs, shear};
    });
  }
}

TEST(UniformGrid, NoParticlesGiveEveryCellAnEmptyRange) {
  const Built b = build(2, {}, kGrid);
  for (std::uint32_t begin : b.grid.cell_begin) ASSERT_EQ(begin, 0u);
}

}  // namespace
}  // namespace dp
