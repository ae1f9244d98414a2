// Rigid particles -> texels by the corrected interpolation of paper Eq. 7
// (Bonet & Kulasegaram 2002), through the simulation as it runs each step.
// References: the analytic fields themselves. Shepard's normalisation
// reproduces constants exactly wherever a particle is in reach; a linear
// field T = a + g.x is reproduced exactly where the weighted mean of the
// neighbours' positions is the texel's own position, which holds at the
// symmetry points of a regular lattice (nodes, edge midpoints, cell
// centres) away from its edges.
#include <gtest/gtest.h>

#include <cfloat>
#include <algorithm>
#include <cmath>

#include "sph/kernel_cubic_spline.h"
#include "surface_scenes.h"

namespace dp {
namespace {

constexpr float kSpacing = 0.01f;
constexpr float kSide = 0.2f;  // 20 spacings
// "Exact to rounding": a float sum of ~13-30 weighted terms and a division,
// relative error a few tens of float epsilons.
constexpr float kRounding = 32 * FLT_EPSILON;

struct PlateRun {
  SimulationSetup setup = test::plate_setup(kSpacing);
  explicit PlateRun(const TexelGeometry& texels) {
    setup.rigid_position = test::plate_particles(kSide, 0.0f, kSpacing);
    SurfaceTextureSetup s;
    s.rigid_first = 0;
    s.rigid_count = setup.rigid_position.size();
    s.texels = texels;
    s.initial_temperature = 123.0f;
    setup.surfaces.push_back(s);
  }
  template <class Field>
  void set_temperatures(const Field& field) {
    setup.rigid_temperature.clear();
    for (const Vec3& x : setup.rigid_position) setup.rigid_temperature.push_back(field(x));
  }
};

float linear(Vec3 x) { return 300.0f + 120.0f * x.x - 70.0f * x.z + 40.0f * x.y; }

TEST(TexelTemperature, ConstantFieldIsExactAtEveryTexelIncludingEdgesAndCorners) {
  // Texels every quarter spacing, beyond the plate's edges by a spacing.
  TexelGeometry texels = test::lattice_texels(89, 0.25f * kSpacing, 0.0f);
  for (Vec3& x : texels.position) x = x - Vec3{kSpacing, 0, kSpacing};
  PlateRun run(texels);
  run.set_temperatures([](Vec3) { return 321.5f; });
  auto sim = make_simulation(ExecutionConfig{Device::Cpu, 2}, run.setup);
  for (int step = 0; step < 2; ++step) {
    const SurfaceSnapshot s = sim->surfaces().at(0);
    ASSERT_EQ(s.size(), texels.size());
    for (std::size_t t = 0; t < s.size(); ++t) ASSERT_NEAR(s.temperature[t], 321.5f, kRounding * 321.5f) << "texel " << t;
    sim->step();
  }
}

TEST(TexelTemperature, LinearFieldIsExactAtLatticeSymmetryPointsAwayFromEdges) {
  // Texels at multiples of half a spacing: nodes, edge midpoints, centres.
  TexelGeometry texels = test::lattice_texels(41, 0.5f * kSpacing, 0.0f);
  PlateRun run(texels);
  run.set_temperatures(linear);
  auto sim = make_simulation(ExecutionConfig{Device::Cpu, 2}, run.setup);
  sim->step();
  const SurfaceSnapshot s = sim->surfaces().at(0);
  const float h = run.setup.support_radius();
  int checked = 0;
  double worst_edge_error = 0;
  for (std::size_t t = 0; t < s.size(); ++t) {
    const Vec3 x = texels.position[t];
    const bool interior = x.x >= h && x.x <= kSide - h && x.z >= h && x.z <= kSide - h;
    if (interior) {
      ASSERT_NEAR(s.temperature[t], linear(x), kRounding * linear(x)) << "texel at " << x.x << ", " << x.z;
      ++checked;
    } else {
      worst_edge_error = std::max(worst_edge_error, std::fabs(static_cast<double>(s.temperature[t]) - linear(x)));
    }
  }
  EXPECT_GT(checked, 500);
  // Near the edges the one-sided neighbourhood shifts the weighted mean
  // inward; the error is then first order, bounded by |g| h.
  const double gradient = std::sqrt(120.0 * 120.0 + 70.0 * 70.0);
  RecordProperty("edge_error_K", std::to_string(worst_edge_error));
  EXPECT_LT(worst_edge_error, gradient * h);
}

TEST(TexelTemperature, OnlyTheTexelsOwnRigidCounts) {
  // A second, hotter plate one spacing above the first is within the
  // kernel's reach of the first plate's texels, but is another rigid.
  TexelGeometry texels = test::lattice_texels(21, kSpacing, 0.0f);
  PlateRun run(texels);
  const std::size_t own = run.setup.rigid_position.size();
  for (const Vec3& x : test::plate_particles(kSide, kSpacing, kSpacing)) run.setup.rigid_position.push_back(x);
  run.setup.rigid_temperature.assign(own, 280.0f);
  run.setup.rigid_temperature.resize(run.setup.rigid_position.size(), 400.0f);
  auto sim = make_simulation(ExecutionConfig{Device::Cpu, 2}, run.setup);
  const SurfaceSnapshot s = sim->surfaces().at(0);
  for (std::size_t t = 0; t < s.size(); ++t) ASSERT_NEAR(s.temperature[t], 280.0f, kRounding * 280.0f);
}

TEST(TexelTemperature, TexelsFollowTheirRigidWhileItWarmsBesideAHeldOne) {
  // The textured plate conducts heat from a second plate held at 400 K one
  // spacing above it. The texels must follow their own plate every step,
  // though the held plate, also within their reach, never changes; the
  // reference is Eq. 7 summed here over the own plate's particles.
  TexelGeometry texels = test::lattice_texels(21, kSpacing, 0.0f);
  PlateRun run(texels);
  run.setup.heat_conduction = true;
  const std::size_t own = run.setup.rigid_position.size();
  for (const Vec3& x : test::plate_particles(kSide, kSpacing, kSpacing)) run.setup.rigid_position.push_back(x);
  run.setup.rigid_temperature.assign(own, 280.0f);
  run.setup.rigid_temperature.resize(run.setup.rigid_position.size(), 400.0f);
  run.setup.rigid_held.assign(own, 0);
  run.setup.rigid_held.resize(run.setup.rigid_position.size(), 1);
  auto sim = make_simulation(ExecutionConfig{Device::Cpu, 2}, run.setup);
  const CubicSplineKernel kernel = CubicSplineKernel::with_support(run.setup.support_radius());
  const std::vector<Vec3> x = sim->rigid_particles();  // sorted, the same order as the next two
  const std::vector<float> volume = sim->rigid_volumes();
  double previous_mean = 280.0;
  for (int step = 0; step < 3; ++step) {
    sim->step();
    const std::vector<float> T = sim->rigid_temperatures();
    const SurfaceSnapshot s = sim->surfaces().at(0);
    double mean = 0;
    for (std::size_t t = 0; t < s.size(); ++t) {
      double sum = 0, weights = 0;
      for (std::size_t k = 0; k < x.size(); ++k) {
        if (x[k].y > 0.5f * kSpacing) continue;  // the held plate: another rigid
        const double w = static_cast<double>(volume[k]) * kernel.W(length(texels.position[t] - x[k]));
        sum += w * T[k];
        weights += w;
      }
      ASSERT_GT(weights, 0.0);
      ASSERT_NEAR(s.temperature[t], sum / weights, kRounding * 400.0f) << "texel " << t << ", step " << step;
      mean += s.temperature[t];
    }
    mean /= static_cast<double>(s.size());
    EXPECT_GT(mean, previous_mean + 1e-3) << "step " << step << ": the plate did not warm";
    previous_mean = mean;
  }
}

TEST(TexelTemperature, TexelsOutOfReachKeepTheirInitialTemperature) {
  TexelGeometry texels = test::lattice_texels(2, 0.01f, 0.1f);  // 0.1 m above the plate, beyond h = 0.02 m
  PlateRun run(texels);
  run.set_temperatures([](Vec3) { return 350.0f; });
  auto sim = make_simulation(ExecutionConfig{Device::Cpu, 1}, run.setup);
  sim->step();
  const SurfaceSnapshot s = sim->surfaces().at(0);
  for (float T : s.temperature) EXPECT_EQ(T, 123.0f);
}

// Not Eq. 7, but the same set-up path: the initial mass texture is
// min(initial * A_t, m_t^max), rounded down to whole texel units.
TEST(SurfaceSetup, InitialMassIsCappedPerTexelAndExact) {
  TexelGeometry texels = test::lattice_texels(30, 0.005f, 0.0f);  // max 0.05 kg/m^2
  PlateRun run(texels);
  run.setup.surfaces[0].initial_mass_per_area = 0.03f;
  run.setup.surfaces[0].texels.max_mass[7] = 0.01f * 0.005f * 0.005f;  // one texel holds less
  auto sim = make_simulation(ExecutionConfig{Device::Cpu, 1}, run.setup);
  const SurfaceSnapshot s = sim->surfaces().at(0);
  double expected = 0;
  for (std::size_t t = 0; t < s.size(); ++t) {
    const double kg = std::min(0.03 * texels.area[t], static_cast<double>(run.setup.surfaces[0].texels.max_mass[t]));
    expected += kg;
    EXPECT_LE(kg_of_texel_units(s.mass_units[t], s.kg_per_unit), kg);
    EXPECT_GT(kg_of_texel_units(s.mass_units[t] + 1, s.kg_per_unit), kg * (1 - 1e-6));
  }
  EXPECT_NEAR(s.total_mass().kg(s.kg_per_unit), expected, 1e-6 * expected);
  EXPECT_NEAR(kg_of_texel_units(s.mass_units[7], s.kg_per_unit), 0.01 * 0.005 * 0.005, 1e-6 * 0.01 * 0.005 * 0.005);
}

TEST(TexelTemperature, SameOnOneAndTwoThreads) {
  TexelGeometry texels = test::lattice_texels(60, 0.37f * kSpacing, 0.0f);
  PlateRun run(texels);
  run.set_temperatures(linear);
  auto a = make_simulation(ExecutionConfig{Device::Cpu, 1}, run.setup);
  auto b = make_simulation(ExecutionConfig{Device::Cpu, 2}, run.setup);
  EXPECT_EQ(a->surfaces().at(0).temperature, b->surfaces().at(0).temperature);
}

}  // namespace
}  // namespace dp
