// Random sequences of merges and redistributions against the conservation
// laws they must keep: mass exactly (integer units), momentum, centre of mass
// and heat up to float rounding; and the drift towards uniform weights that
// Sec. 6.3 asks of them.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <unordered_set>

#include "adaptivity_clouds.h"
#include "backend/cpu_exec.h"

namespace dp {
namespace {

using test::HostParticles;
using test::Totals;

AdaptivityParameters one_round_per_call() {
  AdaptivityParameters p;
  p.search_radius = test::kSupport;
  p.small_weight = 0.5f;
  p.max_rounds = 1;
  return p;
}

bool ids_unique(const HostParticles& h) {
  std::unordered_set<std::uint32_t> seen(h.id.begin(), h.id.end());
  return seen.size() == h.size();
}

TEST(adaptivity_conservation, FiftyRoundsOnARandomCloudConserveMassMomentumAndCentre) {
  constexpr std::size_t kParticles = 5000;
  constexpr int kRounds = 50;
  const HostParticles start = test::random_weight_cloud(kParticles, 2017);
  const Totals before = test::totals_of(start);

  CpuExec exec(2);
  auto particles = test::to_device<CpuExec>(start);
  MassAdaptivity<CpuExec> adaptivity(test::grid_for_box(test::box_side(kParticles)));
  double worst_momentum = 0, worst_centre = 0, worst_heat = 0, worst_extra = 0;
  std::size_t merges = 0, redistributions = 0;
  for (int round = 0; round < kRounds; ++round) {
    const std::size_t n_before = particles.size();
    AdaptivityResult r = adaptivity.adapt(exec, particles, one_round_per_call());
    merges += r.merges;
    redistributions += r.redistributions;
    const HostParticles h = test::to_host(particles);
    const Totals now = test::totals_of(h);

    ASSERT_EQ(now.units, before.units) << "round " << round;
    EXPECT_EQ(r.removed_units, 0);
    // Every merge removes exactly one particle, and nothing else is removed.
    EXPECT_EQ(r.removed_particles, r.merges);
    EXPECT_EQ(h.size(), n_before - r.merges);
    for (MassUnits u : h.units) {
      ASSERT_GT(u, 0u);
      ASSERT_LE(u, kFullParticleUnits);
    }
    ASSERT_TRUE(ids_unique(h)) << "round " << round;

    worst_momentum = std::max(worst_momentum, test::distance(now.momentum, before.momentum) / before.momentum_scale);
    worst_centre = std::max(worst_centre, test::distance(now.first_moment, before.first_moment) /
                                              test::norm(before.first_moment));
    worst_heat = std::max(worst_heat, std::fabs(now.heat - before.heat) / before.heat);
    worst_extra = std::max(worst_extra, std::fabs(now.extra - before.extra) / before.momentum_scale);
  }
  const std::size_t final_count = particles.size();
  std::cout << "[ figures  ] " << kParticles << " -> " << final_count << " particles after " << kRounds
            << " rounds (w < 0.5: " << test::count_below(start, 0.5) << " -> "
            << test::count_below(test::to_host(particles), 0.5) << ")"
            << "; merges " << merges << ", redistributions " << redistributions
            << "; max relative drift: momentum " << worst_momentum << ", centre of mass " << worst_centre
            << ", heat " << worst_heat << "\n";
  RecordProperty("final_particles", std::to_string(final_count));
  RecordProperty("merges", std::to_string(merges));
  RecordProperty("redistributions", std::to_string(redistributions));
  RecordProperty("max_momentum_drift", std::to_string(worst_momentum));
  RecordProperty("max_centre_drift", std::to_string(worst_centre));
  RecordProperty("max_heat_drift", std::to_string(worst_heat));
  EXPECT_GT(merges, 0u);
  EXPECT_GT(redistributions, 0u);
  EXPECT_LT(final_count, kParticles);
  EXPECT_LT(worst_momentum, 1e-6);
  EXPECT_LT(worst_centre, 1e-6);
  EXPECT_LT(worst_heat, 1e-6);
  EXPECT_LT(worst_extra, 1e-6);
}

TEST(adaptivity_conservation, BimodalCloudDriftsTowardsFullWeights) {
  constexpr std::size_t kParticles = 6000;
  const HostParticles start = test::bimodal_cloud(kParticles, 31);
  const std::size_t small_before = test::count_below(start, 0.5);

  CpuExec exec(2);
  auto particles = test::to_device<CpuExec>(start);
  MassAdaptivity<CpuExec> adaptivity(test::grid_for_box(test::box_side(kParticles)));
  std::vector<std::size_t> small_after;
  for (int call = 0; call < 10; ++call) {
    adaptivity.adapt(exec, particles, one_round_per_call());
    small_after.push_back(test::count_below(test::to_host(particles), 0.5));
  }
  const HostParticles end = test::to_host(particles);
  EXPECT_EQ(test::totals_of(end).units, test::totals_of(start).units);
  std::cout << "[ figures  ] bimodal " << kParticles << " particles, " << small_before << " with w < 0.5; after rounds";
  for (std::size_t k = 0; k < small_after.size(); ++k) std::cout << " " << k + 1 << ":" << small_after[k];
  std::cout << "; " << end.size() << " particles left\n";
  RecordProperty("small_before", std::to_string(small_before));
  RecordProperty("small_after_1", std::to_string(small_after.front()));
  RecordProperty("small_after_10", std::to_string(small_after.back()));
  RecordProperty("particles_after_10", std::to_string(end.size()));
  EXPECT_LT(small_after.front(), small_before);
  EXPECT_LT(small_after.back(), small_before / 20);
  for (std::size_t k = 1; k < small_after.size(); ++k) EXPECT_LE(small_after[k], small_after[k - 1]);
}

TEST(adaptivity_conservation, SeveralRoundsInOneCallMatchTheSameCountOfSingleRounds) {
  // Each round re-sorts, so rounds in one call behave like separate calls.
  const HostParticles start = test::random_weight_cloud(2000, 5);
  const UniformGrid grid = test::grid_for_box(test::box_side(2000));
  CpuExec exec(2);
  auto a = test::to_device<CpuExec>(start), b = test::to_device<CpuExec>(start);
  AdaptivityParameters p = one_round_per_call();
  for (int k = 0; k < 4; ++k) adapt_particle_masses(exec, a, grid, p);
  p.max_rounds = 4;
  adapt_particle_masses(exec, b, grid, p);
  const HostParticles ha = test::to_host(a), hb = test::to_host(b);
  EXPECT_EQ(ha.id, hb.id);
  EXPECT_EQ(ha.units, hb.units);
}

}  // namespace
}  // namespace dp
