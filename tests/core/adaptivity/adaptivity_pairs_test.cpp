// Single pairs against Eq. 18 and the redistribution rule of Sec. 6.3,
// computed by hand in double; the partner rule; removal of empty particles.
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

#include "adaptivity_clouds.h"
#include "backend/cpu_exec.h"

namespace dp {
namespace {

using test::HostParticles;

struct Particle {
  Vec3 x, v;
  float temperature;
  MassUnits units;
  float extra;
};

HostParticles make_particles(const std::vector<Particle>& ps) {
  HostParticles h;
  h.extra_count = 1;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    h.position.push_back(ps[i].x);
    h.velocity.push_back(ps[i].v);
    h.temperature.push_back(ps[i].temperature);
    h.units.push_back(ps[i].units);
    h.id.push_back(static_cast<std::uint32_t>(100 + i));
    h.extra.push_back(ps[i].extra);
  }
  return h;
}

UniformGrid small_grid() {
  UniformGrid g;
  g.origin = Vec3{0, 0, 0};
  g.cell_size = test::kSupport;
  g.nx = g.ny = g.nz = 8;
  return g;
}

AdaptivityParameters one_round() {
  AdaptivityParameters p;
  p.search_radius = test::kSupport;
  p.small_weight = 0.5f;
  p.max_rounds = 1;
  return p;
}

struct Outcome {
  HostParticles after;
  AdaptivityResult result;
};

Outcome adapt(const HostParticles& before, AdaptivityParameters params = one_round(), int threads = 1) {
  CpuExec exec(threads);
  auto d = test::to_device<CpuExec>(before);
  Outcome r;
  r.result = adapt_particle_masses(exec, d, small_grid(), params);
  r.after = test::to_host(d);
  return r;
}

std::size_t index_of_id(const HostParticles& h, std::uint32_t id) {
  auto it = std::find(h.id.begin(), h.id.end(), id);
  EXPECT_NE(it, h.id.end()) << "id " << id << " missing";
  return static_cast<std::size_t>(it - h.id.begin());
}

MassUnits units(double w) { return static_cast<MassUnits>(w * kFullParticleUnits); }

// Float results of one blend are within a few ulps of the double reference.
void expect_close(float got, double want) { EXPECT_NEAR(got, want, 4e-7 * std::max(1.0, std::fabs(want))); }

TEST(adaptivity_pairs, MergeGivesTheWeightedMeansOfEq18) {
  const MassUnits ui = units(0.3), uj = units(0.15) + 7;
  HostParticles before = make_particles({{Vec3{0.10f, 0.10f, 0.10f}, Vec3{1.0f, 0.0f, -0.5f}, 300.0f, ui, 2.0f},
                                         {Vec3{0.11f, 0.105f, 0.10f}, Vec3{0.0f, 2.0f, 0.25f}, 350.0f, uj, -1.0f}});
  Outcome r = adapt(before);
  ASSERT_EQ(r.after.size(), 1u);
  EXPECT_EQ(r.result.merges, 1u);
  EXPECT_EQ(r.result.redistributions, 0u);
  EXPECT_EQ(r.result.removed_particles, 1u);
  EXPECT_EQ(r.result.removed_units, 0);
  EXPECT_EQ(r.after.units[0], ui + uj);  // w_n = w_i + w_j, exactly
  EXPECT_EQ(r.after.id[0], 100u);        // the heavier particle's id
  const double wi = ui, wj = uj, wn = wi + wj;
  auto eq18 = [&](float a, float b) { return (a * wi + b * wj) / wn; };
  const Particle p0{before.position[0], before.velocity[0], 0, 0, 0};
  const Particle p1{before.position[1], before.velocity[1], 0, 0, 0};
  expect_close(r.after.position[0].x, eq18(p0.x.x, p1.x.x));
  expect_close(r.after.position[0].y, eq18(p0.x.y, p1.x.y));
  expect_close(r.after.position[0].z, eq18(p0.x.z, p1.x.z));
  expect_close(r.after.velocity[0].x, eq18(p0.v.x, p1.v.x));
  expect_close(r.after.velocity[0].y, eq18(p0.v.y, p1.v.y));
  expect_close(r.after.velocity[0].z, eq18(p0.v.z, p1.v.z));
  expect_close(r.after.temperature[0], eq18(300.0f, 350.0f));
  expect_close(r.after.extra[0], eq18(2.0f, -1.0f));
}

TEST(adaptivity_pairs, MergedParticleKeepsTheHeavierId) {
  HostParticles before = make_particles({{Vec3{0.10f, 0.1f, 0.1f}, Vec3{}, 300.0f, units(0.1), 0.0f},
                                         {Vec3{0.11f, 0.1f, 0.1f}, Vec3{}, 300.0f, units(0.4), 0.0f}});
  Outcome r = adapt(before);
  ASSERT_EQ(r.after.size(), 1u);
  EXPECT_EQ(r.after.id[0], 101u);
  EXPECT_EQ(r.after.units[0], units(0.1) + units(0.4));
}

TEST(adaptivity_pairs, RedistributionLeavesBothAtTheMeanWeight) {
  // w_i + w_j > 1: no merge. The larger gives w_i - (w_i + w_j) / 2; an odd
  // difference leaves its odd unit with the larger particle.
  const MassUnits big = units(0.9) + 1, small = units(0.3);
  ASSERT_EQ((big - small) % 2, 1u);
  HostParticles before = make_particles({{Vec3{0.10f, 0.10f, 0.10f}, Vec3{1.0f, -1.0f, 0.5f}, 360.0f, big, 4.0f},
                                         {Vec3{0.115f, 0.10f, 0.11f}, Vec3{-0.5f, 0.0f, 2.0f}, 290.0f, small, 1.0f}});
  Outcome r = adapt(before);
  ASSERT_EQ(r.after.size(), 2u);
  EXPECT_EQ(r.result.merges, 0u);
  EXPECT_EQ(r.result.redistributions, 1u);
  EXPECT_EQ(r.result.removed_units, 0);
  const std::size_t i = index_of_id(r.after, 100), j = index_of_id(r.after, 101);
  const MassUnits delta = (big - small) / 2;
  EXPECT_EQ(r.after.units[i], big - delta);
  EXPECT_EQ(r.after.units[j], small + delta);
  EXPECT_EQ(r.after.units[i], r.after.units[j] + 1);
  // The giver keeps its own state bit for bit.
  EXPECT_EQ(r.after.position[i].x, before.position[0].x);
  EXPECT_EQ(r.after.velocity[i].y, before.velocity[0].y);
  EXPECT_EQ(r.after.temperature[i], before.temperature[0]);
  EXPECT_EQ(r.after.extra[i], before.extra[0]);
  // The receiver is the mean of itself (weight small) and the giver (weight delta).
  const double ws = small, wd = delta, wn = ws + wd;
  auto mean = [&](float own, float given) { return (own * ws + given * wd) / wn; };
  expect_close(r.after.velocity[j].x, mean(-0.5f, 1.0f));
  expect_close(r.after.velocity[j].y, mean(0.0f, -1.0f));
  expect_close(r.after.velocity[j].z, mean(2.0f, 0.5f));
  expect_close(r.after.position[j].x, mean(0.115f, 0.10f));
  expect_close(r.after.position[j].z, mean(0.11f, 0.10f));
  expect_close(r.after.temperature[j], mean(290.0f, 360.0f));
  expect_close(r.after.extra[j], mean(1.0f, 4.0f));
}

TEST(adaptivity_pairs, ParticlesAtOrAboveTheSmallWeightAreLeftAlone) {
  HostParticles before = make_particles({{Vec3{0.10f, 0.1f, 0.1f}, Vec3{}, 300.0f, units(0.5), 0.0f},
                                         {Vec3{0.11f, 0.1f, 0.1f}, Vec3{}, 300.0f, units(0.7), 0.0f}});
  Outcome r = adapt(before);
  EXPECT_EQ(r.after.size(), 2u);
  EXPECT_EQ(r.result.merges + r.result.redistributions, 0u);
  EXPECT_EQ(r.result.rounds, 0);
}

TEST(adaptivity_pairs, PartnersBeyondTheSearchRadiusAreIgnored) {
  HostParticles before = make_particles({{Vec3{0.10f, 0.1f, 0.1f}, Vec3{}, 300.0f, units(0.2), 0.0f},
                                         {Vec3{0.10f + 1.01f * test::kSupport, 0.1f, 0.1f}, Vec3{}, 300.0f,
                                          units(0.2), 0.0f}});
  Outcome r = adapt(before);
  EXPECT_EQ(r.after.size(), 2u);
  EXPECT_EQ(r.result.merges, 0u);
}

TEST(adaptivity_pairs, MutualChoicePairsTheClosestAndLeavesTheThirdAlone) {
  // b's nearest is c and c's nearest is b: that pair forms; a chose b and is
  // not chosen back, so it waits for the next round.
  HostParticles before = make_particles({{Vec3{0.100f, 0.1f, 0.1f}, Vec3{}, 300.0f, units(0.2), 0.0f},
                                         {Vec3{0.108f, 0.1f, 0.1f}, Vec3{}, 300.0f, units(0.2), 0.0f},
                                         {Vec3{0.113f, 0.1f, 0.1f}, Vec3{}, 300.0f, units(0.2), 0.0f}});
  Outcome r = adapt(before);
  ASSERT_EQ(r.after.size(), 2u);
  EXPECT_EQ(r.result.merges, 1u);
  const std::size_t a = index_of_id(r.after, 100), bc = index_of_id(r.after, 101);
  EXPECT_EQ(r.after.units[a], units(0.2));
  EXPECT_EQ(r.after.units[bc], 2 * units(0.2));
  EXPECT_FLOAT_EQ(r.after.position[bc].x, 0.1105f);

  AdaptivityParameters more = one_round();
  more.max_rounds = 3;
  Outcome r3 = adapt(before, more);
  ASSERT_EQ(r3.after.size(), 1u);  // 0.2 + 0.4 <= 1 merges in round two
  EXPECT_EQ(r3.after.units[0], 3 * units(0.2));
  EXPECT_EQ(r3.result.rounds, 2);
}

TEST(adaptivity_pairs, MergingTakesPriorityOverACloserRedistribution) {
  HostParticles before = make_particles({{Vec3{0.100f, 0.1f, 0.1f}, Vec3{}, 300.0f, units(0.2), 0.0f},
                                         {Vec3{0.102f, 0.1f, 0.1f}, Vec3{}, 300.0f, units(1.0), 0.0f},
                                         {Vec3{0.090f, 0.1f, 0.1f}, Vec3{}, 300.0f, units(0.3), 0.0f}});
  Outcome r = adapt(before);
  ASSERT_EQ(r.after.size(), 2u);
  EXPECT_EQ(r.result.merges, 1u);
  EXPECT_EQ(r.result.redistributions, 0u);
  EXPECT_EQ(r.after.units[index_of_id(r.after, 101)], units(1.0));
}

TEST(adaptivity_pairs, EqualWeightsAboveHalfAreNotRedistributed) {
  // With a small weight above 0.5 two equal particles qualify by size but
  // have nothing to even out.
  HostParticles before = make_particles({{Vec3{0.10f, 0.1f, 0.1f}, Vec3{}, 300.0f, units(0.6), 0.0f},
                                         {Vec3{0.11f, 0.1f, 0.1f}, Vec3{}, 300.0f, units(0.6), 0.0f}});
  AdaptivityParameters p = one_round();
  p.small_weight = 0.8f;
  Outcome r = adapt(before, p);
  EXPECT_EQ(r.result.merges + r.result.redistributions, 0u);
  EXPECT_EQ(r.after.units[0], units(0.6));
  EXPECT_EQ(r.after.units[1], units(0.6));
}

TEST(adaptivity_pairs, RemoveEmptyKeepsTheOrderOfTheOthers) {
  HostParticles before;
  before.extra_count = 2;
  const std::vector<MassUnits> u = {5, 0, 7, 0, 0, 9, 0};
  for (std::size_t i = 0; i < u.size(); ++i) {
    before.position.push_back(Vec3{float(i), 0, 0});
    before.velocity.push_back(Vec3{0, float(i), 0});
    before.temperature.push_back(300.0f + i);
    before.units.push_back(u[i]);
    before.id.push_back(static_cast<std::uint32_t>(i));
  }
  for (std::size_t a = 0; a < 2; ++a)
    for (std::size_t i = 0; i < u.size(); ++i) before.extra.push_back(10.0f * a + i);
  CpuExec exec(2);
  auto d = test::to_device<CpuExec>(before);
  MassAdaptivity<CpuExec> adaptivity(small_grid());
  EXPECT_EQ(adaptivity.remove_empty(exec, d), 4u);
  HostParticles h = test::to_host(d);
  EXPECT_EQ(h.id, (std::vector<std::uint32_t>{0, 2, 5}));
  EXPECT_EQ(h.units, (std::vector<MassUnits>{5, 7, 9}));
  EXPECT_EQ(h.temperature, (std::vector<float>{300.0f, 302.0f, 305.0f}));
  EXPECT_EQ(h.velocity[2].y, 5.0f);
  EXPECT_EQ(h.extra, (std::vector<float>{0.0f, 2.0f, 5.0f, 10.0f, 12.0f, 15.0f}));
  EXPECT_EQ(adaptivity.remove_empty(exec, d), 0u);
}

TEST(adaptivity_pairs, AdaptDropsParticlesThatCameInEmpty) {
  HostParticles before = make_particles({{Vec3{0.10f, 0.1f, 0.1f}, Vec3{}, 300.0f, units(1.0), 0.0f},
                                         {Vec3{0.11f, 0.1f, 0.1f}, Vec3{}, 300.0f, 0, 0.0f},
                                         {Vec3{0.12f, 0.1f, 0.1f}, Vec3{}, 300.0f, units(0.9), 0.0f}});
  Outcome r = adapt(before);
  EXPECT_EQ(r.after.size(), 2u);
  EXPECT_EQ(r.result.removed_particles, 1u);
  EXPECT_EQ(r.result.removed_units, 0);
}

TEST(adaptivity_pairs, SearchRadiusBeyondTheCellSizeIsRejected) {
  HostParticles before = make_particles({{Vec3{0.10f, 0.1f, 0.1f}, Vec3{}, 300.0f, units(0.2), 0.0f}});
  AdaptivityParameters p = one_round();
  p.search_radius = 1.5f * test::kSupport;
  EXPECT_THROW(adapt(before, p), std::invalid_argument);
}

TEST(adaptivity_pairs, ArraysOfDifferentLengthsAreRejected) {
  HostParticles before = make_particles({{Vec3{0.10f, 0.1f, 0.1f}, Vec3{}, 300.0f, units(0.2), 0.0f},
                                         {Vec3{0.11f, 0.1f, 0.1f}, Vec3{}, 300.0f, units(0.2), 0.0f}});
  before.extra_count = 2;  // but only one value per particle
  EXPECT_THROW(adapt(before), std::invalid_argument);
}

}  // namespace
}  // namespace dp
