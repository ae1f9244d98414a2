// Surface tension (Akinci et al. 2013) through the full step: a cube of
// liquid without gravity becomes a ball. Reference: the shape of a ball,
// whose farthest point lies sqrt(5/3) = 1.291 radii of gyration out
// (a cube's corners lie sqrt(3) = 1.732 out).
#include <gtest/gtest.h>

#include <cmath>

#include "tank.h"

namespace dp {
namespace {

double reach_ratio(const ParticleSnapshot& p) {
  Vec3 c{};
  for (const Vec3& x : p.position) c += (1.0f / p.size()) * x;
  double gyration = 0, reach = 0;
  for (const Vec3& x : p.position) {
    gyration += length_squared(x - c) / p.size();
    reach = std::max(reach, static_cast<double>(length(x - c)));
  }
  return reach / std::sqrt(gyration);
}

TEST(SurfaceTension, CubeWithoutGravityBecomesABall) {
  SimulationSetup setup;
  setup.particle_spacing = 0.01f;
  setup.gravity = Vec3{};
  setup.liquid.surface_tension = 1.0f;
  setup.liquid.xsph_epsilon = 0.05f;
  test::add_block(setup, Vec3{-0.045f, -0.045f, -0.045f}, 10, 10, 10);
  setup.domain_min = Vec3{-0.3f, -0.3f, -0.3f};
  setup.domain_max = Vec3{0.3f, 0.3f, 0.3f};
  auto sim = make_simulation(ExecutionConfig{Device::Cpu, 0}, setup);
  const double before = reach_ratio(sim->particles());
  sim->advance_to(0.6);
  const double after = reach_ratio(sim->particles());
  sim->advance_to(0.8);
  const double later = reach_ratio(sim->particles());
  RecordProperty("reach_ratio_before", std::to_string(before));
  RecordProperty("reach_ratio_after", std::to_string(after));
  RecordProperty("reach_ratio_later", std::to_string(later));
  const double ball = std::sqrt(5.0 / 3.0);
  EXPECT_NEAR(after, ball, 0.1 * ball);
  EXPECT_NEAR(later, ball, 0.1 * ball);  // and it stays one
  EXPECT_EQ(sim->particles().size(), 1000u);
}

}  // namespace
}  // namespace dp
