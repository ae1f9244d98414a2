// Alg. 1 line 19, the particle path force as defined in
// coupling/path_force.h: wet texels raise the adhesion of the boundary
// particles under them. Checked: the transposed interpolation reproduces
// constant and linear wetting fields; with nothing wet the step is exactly
// the step without the force; a drop sliding down a plate with a wet trail
// beside its line of descent turns towards the trail, and without the force
// it does not.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../surface/surface_scenes.h"
#include "coupling/path_force.h"
#include "simulation.h"

namespace dp {
namespace {

constexpr float kSpacing = 0.01f;
constexpr float kPi = 3.14159265f;

// A texel -> rigid list of texels on a lattice and rigid particles on
// another, with Eq. 7-like weights (cubic spline, normalised per texel).
struct TwoLattices {
  std::vector<Vec3> texel, rigid;
  std::vector<std::uint32_t> offset{0}, index;
  std::vector<float> weight, area;
  TwoLattices() {
    const CubicSplineKernel kernel = CubicSplineKernel::with_support(2 * kSpacing);
    for (int j = 0; j < 21; ++j)
      for (int i = 0; i < 21; ++i) rigid.push_back(Vec3{i * kSpacing, 0, j * kSpacing});
    for (int j = 0; j < 41; ++j)
      for (int i = 0; i < 41; ++i) texel.push_back(Vec3{i * 0.005f, 0, j * 0.005f});
    for (const Vec3& xt : texel) {
      float norm = 0;
      const std::size_t first = index.size();
      for (std::size_t k = 0; k < rigid.size(); ++k) {
        const float w = kernel.W(length(xt - rigid[k]));
        if (w <= 0) continue;
        index.push_back(static_cast<std::uint32_t>(k));
        weight.push_back(w);
        norm += w;
      }
      for (std::size_t e = first; e < index.size(); ++e) weight[e] /= norm;
      offset.push_back(static_cast<std::uint32_t>(index.size()));
      area.push_back(0.005f * 0.005f);
    }
  }
  std::vector<float> gather(const std::vector<float>& wetting) const {
    const RigidTexelList list = transpose_texel_rigid_list(offset, index, weight, area, rigid.size());
    std::vector<float> out(rigid.size(), -1.0f);
    const GatherRigidWetting g{list.offset.data(), list.texel.data(), list.weight.data(), wetting.data(), out.data()};
    for (std::size_t k = 0; k < rigid.size(); ++k) g(k);
    return out;
  }
};

TEST(coupling_PathForce, TransposedInterpolationKeepsConstantAndInteriorLinearWetting) {
  const TwoLattices l;
  const std::vector<float> constant = l.gather(std::vector<float>(l.texel.size(), 0.7f));
  for (float w : constant) EXPECT_NEAR(w, 0.7f, 1e-6f);
  // A linear field is exact where the texels around a particle are
  // symmetric about it: away from the lattice's edges.
  std::vector<float> linear(l.texel.size());
  for (std::size_t t = 0; t < l.texel.size(); ++t) linear[t] = 0.2f + 2.0f * l.texel[t].x + 1.0f * l.texel[t].z;
  const std::vector<float> gathered = l.gather(linear);
  for (std::size_t k = 0; k < l.rigid.size(); ++k) {
    const Vec3 x = l.rigid[k];
    if (x.x < 0.025f || x.x > 0.175f || x.z < 0.025f || x.z > 0.175f) continue;
    EXPECT_NEAR(gathered[k], 0.2f + 2.0f * x.x + 1.0f * x.z, 1e-5f) << "particle at " << x.x << ", " << x.z;
  }
}

// A drop of 3^3 particles on a 0.3 m x 0.2 m plate, gravity tilted by 20
// degrees towards +x, so that the drop slides along x at z = 0.1 m.
SimulationSetup sliding_drop(bool path_force, bool wet_trail) {
  SimulationSetup s = test::plate_setup(kSpacing);
  s.domain_min = Vec3{-0.05f, -0.05f, -0.05f};
  s.domain_max = Vec3{0.35f, 0.2f, 0.25f};
  const float tilt = 20.0f * kPi / 180.0f;
  s.gravity = Vec3{9.81f * std::sin(tilt), -9.81f * std::cos(tilt), 0};
  s.liquid.surface_tension = 1.0f;
  s.liquid.boundary_friction = 0.05f;
  std::vector<std::array<float, 3>> p{{0, 0, 0}, {0.3f, 0, 0}, {0.3f, 0, 0.2f}, {0, 0, 0.2f}};
  std::vector<std::array<std::uint32_t, 3>> t{{0, 2, 1}, {0, 3, 2}};
  s.rigid_position = sample_surface(p, t, kSpacing);
  s.rigid_adhesion.assign(s.rigid_position.size(), 2.0f);
  SurfaceTextureSetup tex;
  tex.rigid_count = s.rigid_position.size();
  const float step = 0.005f;
  for (int j = 0; j <= 40; ++j)
    for (int i = 0; i <= 60; ++i) {
      tex.texels.pixel.push_back(static_cast<std::uint32_t>(j * 61 + i));
      tex.texels.position.push_back(Vec3{i * step, 0, j * step});
      tex.texels.normal.push_back(Vec3{0, 1, 0});
      tex.texels.area.push_back(step * step);
      tex.texels.max_mass.push_back(0);
    }
  tex.texels.width = 61;
  tex.texels.height = 41;
  tex.wetting_decay = 100.0f;  // the trail stays for the whole run
  if (wet_trail) {
    // A wet band 3 cm wide from the drop's start, 30 degrees off the line of descent towards +z.
    const Vec3 start{0.06f, 0, 0.1f}, along{std::cos(kPi / 6), 0, std::sin(kPi / 6)};
    for (const Vec3& x : tex.texels.position) {
      const Vec3 d = x - start;
      const float s_along = dot(d, along);
      const float across = length(d - s_along * along);
      tex.initial_wetting.push_back(s_along > -0.01f && across < 0.015f ? 1.0f : 0.0f);
    }
  }
  s.surfaces.push_back(tex);
  s.coupling.path_force = path_force;
  s.coupling.path_adhesion = 12.0f;  // six times the wall's adhesion
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) s.liquid_position.push_back(Vec3{0.05f + i * kSpacing, kSpacing * (1 + j), 0.09f + k * kSpacing});
  s.liquid_velocity.assign(s.liquid_position.size(), Vec3{});
  return s;
}

Vec3 centroid(const ParticleSnapshot& p) {
  Vec3 c{0, 0, 0};
  for (const Vec3& x : p.position) c = c + x;
  return (1.0f / static_cast<float>(p.size())) * c;
}

TEST(coupling_PathForce, AUniformlyWetSurfaceLeavesTheStepAsWithoutIt) {
  // Every texel wet and staying wet (the history cannot fade in this run):
  // every W_k equals the local average, so the force is zero and the drop
  // must move exactly, bit for bit, as without the force.
  SimulationSetup wet = sliding_drop(true, false);
  wet.surfaces[0].initial_wetting.assign(wet.surfaces[0].texels.size(), 1.0f);
  wet.surfaces[0].wetting_decay = 1e30f;
  auto a_sim = make_simulation(ExecutionConfig{Device::Cpu, 2}, wet);
  auto b_sim = make_simulation(ExecutionConfig{Device::Cpu, 2}, sliding_drop(false, false));
  a_sim->advance_to(0.05);
  b_sim->advance_to(0.05);
  const ParticleSnapshot a = a_sim->particles(), b = b_sim->particles();
  ASSERT_EQ(a.size(), b.size());
  ASSERT_GT(a_sim->step_count(), 5);
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a.position[i].x, b.position[i].x);
    EXPECT_EQ(a.position[i].z, b.position[i].z);
    EXPECT_EQ(a.velocity[i].x, b.velocity[i].x);
  }
}

TEST(coupling_PathForce, ASlidingDropTurnsTowardsAWetTrail) {
  const double duration = 0.4;  // the drop slides about 0.2 m, staying on the plate
  auto run = [&](bool path_force) {
    auto sim = make_simulation(ExecutionConfig{Device::Cpu, 2}, sliding_drop(path_force, true));
    const Vec3 start = centroid(sim->particles());
    sim->advance_to(duration);
    const ParticleSnapshot p = sim->particles();
    EXPECT_EQ(p.size(), 27u) << "the drop stays one drop of 27 particles";
    return centroid(p) - start;
  };
  const Vec3 with = run(true), without = run(false);
  std::printf("drop displacement with the path force (%.4f, %.4f) m, without (%.4f, %.4f) m (x, z)\n", with.x, with.z,
              without.x, without.z);
  ASSERT_GT(without.x, 0.03f) << "the drop must slide for the test to mean anything";
  ASSERT_GT(with.x, 0.03f);
  // Without the force the drop runs straight down (the scene is symmetric
  // about z = 0.1 m but for the trail, which it does not feel).
  EXPECT_LT(std::fabs(without.z), 0.05f * without.x);
  // With it the drop follows the trail, 30 degrees off the line of descent
  // (tan 30 = 0.58): at least a third of that angle.
  EXPECT_GT(with.z / with.x, std::tan(kPi / 18));
}

}  // namespace
}  // namespace dp
