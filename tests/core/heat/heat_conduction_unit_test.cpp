// Properties of the heat conduction kernels that hold for any particle
// arrangement: determinism across thread counts, antisymmetric pair
// exchange (energy conservation with adaptive masses and two materials),
// the direction of heat flow, held particles, and the time-step limit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <vector>

#include "heat_scene.h"
#include "sph/heat_cleary_monaghan1999.h"
#include "sph/neighbor_list.h"
#include "sph/sum_in_list_order.h"
#include "sph/surface_tension_akinci2013.h"
#include "sph/transposed_list.h"

namespace dp {
namespace {

using heat_test::SortedSet;

constexpr float kSpacing = 0.01f;

// A disordered liquid (random weights, densities and temperatures) next to
// a disordered rigid set of another material (random volumes).
struct MixedScene {
  CubicSplineKernel kernel = CubicSplineKernel::with_support(2.0f * kSpacing);
  SortedSet liquid, rigid;
  std::vector<float> liquid_t, rigid_t, density, volume;
  std::vector<MassUnits> units;
  float particle_mass = 1000.0f * kSpacing * kSpacing * kSpacing;
  heat_test::MassesAndVolumes liquid_amounts;

  // `clump` more liquid particles packed within 1 mm of a point 2 mm above
  // the rigid set: their lists, and those of the rigid particles below,
  // outgrow the in-order sums' arrays (kMaxTermsInOrder).
  explicit MixedScene(const CpuExec& exec, int clump = 0) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<Vec3> pl, pr;
    for (int i = 0; i < 3000; ++i) pl.push_back(0.12f * Vec3{u(rng), u(rng), u(rng)});
    for (int i = 0; i < 1500; ++i) pr.push_back(Vec3{0.12f * u(rng), 0.12f * u(rng), -0.06f * u(rng)});
    std::mt19937 clump_rng(13);
    std::uniform_real_distribution<float> c(-1e-3f, 1e-3f);
    for (int i = 0; i < clump; ++i) pl.push_back(Vec3{0.06f, 0.06f, 0.002f} + Vec3{c(clump_rng), c(clump_rng), c(clump_rng)});
    UniformGrid grid = heat_test::grid_around({pl, pr}, kernel.h);
    liquid = heat_test::sort_into(exec, pl, grid);
    rigid = heat_test::sort_into(exec, pr, grid);
    for (std::size_t i = 0; i < pl.size(); ++i) {
      liquid_t.push_back(280.0f + 60.0f * u(rng));
      density.push_back(900.0f + 200.0f * u(rng));
      units.push_back(static_cast<MassUnits>((0.3f + 0.7f * u(rng)) * kFullParticleUnits));
    }
    for (std::size_t i = 0; i < pr.size(); ++i) {
      rigid_t.push_back(280.0f + 60.0f * u(rng));
      volume.push_back((0.5f + u(rng)) * kSpacing * kSpacing * kSpacing);
    }
    liquid_amounts = heat_test::masses_and_volumes(units, density, particle_mass);
  }
  ThermalParticles liquid_particles() {
    return ThermalParticles::liquid(liquid.view(), liquid_t.data(), liquid_amounts.mass.data(),
                                    liquid_amounts.volume.data(), 0.6f, 4186.0f);
  }
  ThermalParticles rigid_particles() {
    return ThermalParticles::rigid(rigid.view(), rigid_t.data(), volume.data(), 7850.0f, 50.0f, 490.0f);
  }
};

struct Rates {
  std::vector<float> liquid, rigid;
};

Rates rates_with(int threads) {
  CpuExec exec(threads);
  MixedScene scene(exec);
  Rates r;
  r.liquid.resize(scene.liquid.size());
  r.rigid.resize(scene.rigid.size());
  ThermalParticles l = scene.liquid_particles(), b = scene.rigid_particles();
  exec.parallel_for(r.liquid.size(), ComputeTemperatureRate{l, b, true, scene.kernel, r.liquid.data()});
  exec.parallel_for(r.rigid.size(), ComputeTemperatureRate{b, l, true, scene.kernel, r.rigid.data()});
  return r;
}

bool bitwise_equal(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

TEST(heat_Determinism, RatesAreBitIdenticalForAnyThreadCount) {
  Rates one = rates_with(1);
  for (int threads : {2, 3, 8}) {
    Rates many = rates_with(threads);
    EXPECT_TRUE(bitwise_equal(one.liquid, many.liquid)) << threads << " threads, liquid";
    EXPECT_TRUE(bitwise_equal(one.rigid, many.rigid)) << threads << " threads, rigid";
  }
}

// sum_i m_i C_i dT_i/dt vanishes pair by pair, so only rounding remains:
// compared with the sum of the terms' magnitudes.
// The step hands the kernels its neighbour lists with each pair's gradient
// factor (FillNeighbors); the lists are filled by the grid walk, so the sums
// must come out bit for bit as the walk's. A list out of the walk's order,
// or a factor that is not gradW's, fails here.
TEST(heat_NeighbourLists, ListedPairsGiveTheGridWalksRatesAndNormalsBitForBit) {
  CpuExec exec(2);
  MixedScene scene(exec);
  NeighborListBuffers<CpuExec> liquid_liquid, liquid_rigid, rigid_rigid;
  const ListedPairs ll = liquid_liquid.build_with_gradients(exec, scene.liquid.position, scene.liquid.view(), scene.kernel);
  const ListedPairs lr = liquid_rigid.build_with_gradients(exec, scene.liquid.position, scene.rigid.view(), scene.kernel);
  const ListedPairs rr = rigid_rigid.build_with_gradients(exec, scene.rigid.position, scene.rigid.view(), scene.kernel);
  ASSERT_GT(liquid_liquid.index.size(), 20 * scene.liquid.size());  // the pairs are there to be compared
  ASSERT_GT(liquid_rigid.index.size(), scene.liquid.size());

  const ThermalParticles l = scene.liquid_particles(), b = scene.rigid_particles();
  const std::size_t n = scene.liquid.size(), m = scene.rigid.size();
  std::vector<float> walked(n), listed(n), rigid_walked(m), rigid_listed(m);
  exec.parallel_for(n, ComputeTemperatureRate{l, b, true, scene.kernel, walked.data()});
  exec.parallel_for(n, ComputeTemperatureRate{l, b, true, scene.kernel, listed.data(), ll, lr});
  exec.parallel_for(m, ComputeTemperatureRate{b, l, true, scene.kernel, rigid_walked.data()});
  exec.parallel_for(m, ComputeTemperatureRate{b, l, true, scene.kernel, rigid_listed.data(), rr});
  EXPECT_TRUE(bitwise_equal(walked, listed));
  EXPECT_TRUE(bitwise_equal(rigid_walked, rigid_listed));

  std::vector<Vec3> normal_walked(n), normal_listed(n);
  exec.parallel_for(n, ComputeSurfaceNormal{scene.liquid.view(), scene.units.data(), scene.density.data(), scene.kernel,
                                            scene.particle_mass, normal_walked.data()});
  exec.parallel_for(n, ComputeSurfaceNormal{scene.liquid.view(), scene.units.data(), scene.density.data(), scene.kernel,
                                            scene.particle_mass, normal_listed.data(), ll});
  EXPECT_EQ(0, std::memcmp(normal_walked.data(), normal_listed.data(), n * sizeof(Vec3)));
}

// On the CPU, ComputeTemperatureRate::whole_range computes each list's
// terms first and adds them in the list's order, and takes the liquid
// around a rigid particle from the liquid's rigid lists seen from the rigid
// side (TransposedList) or walks the grid for it with gather_near; the GPU
// runs the functor's one loop. All must give the same bits, for listed,
// transposed and walked neighbours, and for lists too long for the terms'
// arrays. A sum added out of the list's order, or a pair gathered out of
// the walk's, fails here; so does a transposed list that differs from the
// walk's pairs, which is also compared with gather_near itself.
TEST(heat_NeighbourLists, SumsInListOrderAreTheOneLoopSumsBitForBit) {
  CpuExec exec(2);
  MixedScene scene(exec, 400);
  NeighborListBuffers<CpuExec> liquid_liquid, liquid_rigid, rigid_rigid;
  const ListedPairs ll = liquid_liquid.build_with_gradients(exec, scene.liquid.position, scene.liquid.view(), scene.kernel);
  const ListedPairs lr = liquid_rigid.build_with_gradients(exec, scene.liquid.position, scene.rigid.view(), scene.kernel);
  const ListedPairs rr = rigid_rigid.build_with_gradients(exec, scene.rigid.position, scene.rigid.view(), scene.kernel);
  const std::size_t n = scene.liquid.size(), m = scene.rigid.size();
  std::uint32_t longest = 0;
  for (std::size_t i = 0; i < n; ++i) longest = std::max(longest, ll.list.offset[i + 1] - ll.list.offset[i]);
  ASSERT_GT(longest, kMaxTermsInOrder);   // the one-loop fallback is taken too
  ASSERT_GT(lr.list.offset[n], n / 10);  // pairs across the sets, walked from the rigid side

  const ThermalParticles l = scene.liquid_particles(), b = scene.rigid_particles();
  const auto one_loop = [](std::size_t count, const ComputeTemperatureRate& rate) {
    for (std::size_t i = 0; i < count; ++i) rate(i);
  };
  TransposedList transposed;
  const NeighborList liquid_near_rigid = transposed.build(lr.list, n, m);
  const GridView liquid_grid = scene.liquid.view();
  for (std::size_t k = 0; k < m; ++k) {
    const Vec3 xk = scene.rigid.position[k];
    std::vector<std::uint32_t> walked;  // as gather_near takes them, also past its capacity
    liquid_grid.for_each_near(xk, [&](std::uint32_t j) {
      if (length_squared(xk - liquid_grid.position[j]) < scene.kernel.h * scene.kernel.h) walked.push_back(j);
    });
    const std::vector<std::uint32_t> listed(liquid_near_rigid.index + liquid_near_rigid.offset[k],
                                            liquid_near_rigid.index + liquid_near_rigid.offset[k + 1]);
    ASSERT_EQ(listed, walked) << "rigid particle " << k;
  }
  for (int mode : {0, 1, 2}) {  // walked, listed, listed with the rigid side's liquid transposed
    const bool listed = mode > 0;
    std::vector<float> split(n), single(n), rigid_split(m), rigid_single(m);
    const ListedPairs none{};
    const ComputeTemperatureRate liquid_rate{l, b, true, scene.kernel, split.data(), listed ? ll : none, listed ? lr : none};
    ComputeTemperatureRate rigid_rate{b, l, true, scene.kernel, rigid_split.data(), listed ? rr : none};
    if (mode == 2) rigid_rate.other_near = liquid_near_rigid;
    exec.parallel_for(n, liquid_rate);
    exec.parallel_for(m, rigid_rate);
    ComputeTemperatureRate liquid_single = liquid_rate, rigid_single_rate = rigid_rate;
    liquid_single.rate = single.data();
    rigid_single_rate.rate = rigid_single.data();
    one_loop(n, liquid_single);
    one_loop(m, rigid_single_rate);
    EXPECT_TRUE(bitwise_equal(split, single)) << "mode " << mode << ", liquid";
    EXPECT_TRUE(bitwise_equal(rigid_split, rigid_single)) << "mode " << mode << ", rigid";
  }
}

TEST(heat_Conservation, HeatPowersCancelAcrossSetsWithAdaptiveMasses) {
  CpuExec exec(2);
  MixedScene scene(exec);
  Rates r = rates_with(2);
  ThermalParticles l = scene.liquid_particles(), b = scene.rigid_particles();
  double net = 0, magnitude = 0;
  auto add = [&](const ThermalParticles& p, const std::vector<float>& rate) {
    for (std::size_t i = 0; i < rate.size(); ++i) {
      double power = double(p.mass_of(static_cast<std::uint32_t>(i))) * p.specific_heat * rate[i];
      net += power;
      magnitude += std::fabs(power);
    }
  };
  add(l, r.liquid);
  add(b, r.rigid);
  ASSERT_GT(magnitude, 0.0);
  EXPECT_LT(std::fabs(net) / magnitude, 1e-5);
}

// Two particles of different materials and masses: the hot one cools, the
// cold one warms, and the powers are opposite.
TEST(heat_Conservation, HeatFlowsFromHotToCold) {
  CpuExec exec(1);
  const CubicSplineKernel kernel = CubicSplineKernel::with_support(2.0f * kSpacing);
  std::vector<Vec3> pl{Vec3{0, 0, 0}}, pr{Vec3{0.013f, 0.002f, 0}};
  UniformGrid grid = heat_test::grid_around({pl, pr}, kernel.h);
  SortedSet liquid = heat_test::sort_into(exec, pl, grid), rigid = heat_test::sort_into(exec, pr, grid);
  std::vector<float> tl{350.0f}, tr{300.0f}, density{980.0f}, volume{2e-6f}, rl(1), rr(1);
  std::vector<MassUnits> units{kFullParticleUnits / 3};
  const heat_test::MassesAndVolumes amounts = heat_test::masses_and_volumes(units, density, 1e-3f);
  ThermalParticles l = ThermalParticles::liquid(liquid.view(), tl.data(), amounts.mass.data(), amounts.volume.data(),
                                                0.6f, 4186.0f);
  ThermalParticles b = ThermalParticles::rigid(rigid.view(), tr.data(), volume.data(), 2700.0f, 200.0f, 900.0f);
  ComputeTemperatureRate{l, b, true, kernel, rl.data()}(0);
  ComputeTemperatureRate{b, l, true, kernel, rr.data()}(0);
  EXPECT_LT(rl[0], 0.0f);
  EXPECT_GT(rr[0], 0.0f);
  double pl_power = double(l.mass_of(0)) * l.specific_heat * rl[0];
  double pr_power = double(b.mass_of(0)) * b.specific_heat * rr[0];
  EXPECT_NEAR(pl_power, -pr_power, 1e-6 * std::fabs(pr_power));
}

TEST(heat_Conservation, PairConductivityIsTwiceTheHarmonicMean) {
  EXPECT_FLOAT_EQ(pair_conductivity(0.6f, 0.6f), 1.2f);
  EXPECT_FLOAT_EQ(pair_conductivity(0.6f, 2.4f), pair_conductivity(2.4f, 0.6f));
  EXPECT_FLOAT_EQ(pair_conductivity(0.6f, 2.4f), 4.0f * 0.6f * 2.4f / 3.0f);
  EXPECT_EQ(pair_conductivity(0.6f, 0.0f), 0.0f);  // an insulator passes no heat
  EXPECT_EQ(pair_conductivity(0.0f, 0.0f), 0.0f);
}

TEST(heat_Integration, HeldParticlesKeepTheirTemperature) {
  std::vector<float> rate{5.0f, -3.0f, 2.0f}, t{300.0f, 423.15f, 310.0f};
  std::vector<std::uint8_t> held{0, 1, 0};
  CpuExec exec(1);
  exec.parallel_for(3, IntegrateTemperature{rate.data(), held.data(), 0.5f, t.data()});
  EXPECT_FLOAT_EQ(t[0], 302.5f);
  EXPECT_EQ(t[1], 423.15f);
  EXPECT_FLOAT_EQ(t[2], 311.0f);
  exec.parallel_for(3, IntegrateTemperature{rate.data(), nullptr, 1.0f, t.data()});
  EXPECT_FLOAT_EQ(t[1], 420.15f);
}

// At the limit, every step's new temperature is a convex combination of the
// old ones: a random field on the lattice never leaves its initial range.
TEST(heat_Integration, TimeStepLimitKeepsTheMaximumPrinciple) {
  const CubicSplineKernel kernel = CubicSplineKernel::with_support(2.0f * kSpacing);
  const float rho = 1000.0f, c = 4186.0f, kappa = 0.6f;
  EXPECT_FLOAT_EQ(heat_time_step_limit(kernel, rho, c, kappa), rho * c * kernel.h * kernel.h / (24.0f * kappa));

  CpuExec exec(2);
  std::vector<Vec3> p = heat_test::lattice_block(Vec3{}, 12, 12, 12, kSpacing);
  SortedSet set = heat_test::sort_into(exec, p, heat_test::grid_around({p}, kernel.h));
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<float> t(p.size()), rate(p.size()), density(p.size(), rho);
  for (float& x : t) x = u(rng) < 0.5f ? 0.0f : 1.0f;  // the roughest field: jumps everywhere
  std::vector<MassUnits> units(p.size(), kFullParticleUnits);
  const heat_test::MassesAndVolumes amounts =
      heat_test::masses_and_volumes(units, density, rho * kSpacing * kSpacing * kSpacing);
  ThermalParticles water =
      ThermalParticles::liquid(set.view(), t.data(), amounts.mass.data(), amounts.volume.data(), kappa, c);
  const float dt = heat_time_step_limit(kernel, rho, c, kappa);
  for (int step = 0; step < 20; ++step) {
    exec.parallel_for(p.size(), ComputeTemperatureRate{water, water, false, kernel, rate.data()});
    exec.parallel_for(p.size(), IntegrateTemperature{rate.data(), nullptr, dt, t.data()});
    for (float x : t) {
      ASSERT_GE(x, -1e-5f) << "step " << step;
      ASSERT_LE(x, 1.0f + 1e-5f) << "step " << step;
    }
  }
}

}  // namespace
}  // namespace dp
