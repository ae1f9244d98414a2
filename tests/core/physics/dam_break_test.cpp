// Dam break against Martin & Moyce 1952 ("An experimental study of the
// collapse of liquid columns on a rigid horizontal plane", Phil. Trans. A
// 244, Plate/Table for the square column n^2 = 2): a column of width a and
// height 2a collapses; the surge front Z = x/a against T = t sqrt(2g/a).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "tank.h"

namespace dp {
namespace {

struct Sample {
  double T, Z;
};

// Martin & Moyce 1952, a = 2.25 in, as given in issue #3.
const Sample kMartinMoyce[] = {{0.41, 1.11}, {0.84, 1.22}, {1.19, 1.44}, {1.43, 1.67}, {1.63, 1.89},
                               {1.83, 2.11}, {1.98, 2.33}, {2.20, 2.56}, {2.32, 2.78}, {2.51, 3.00},
                               {2.65, 3.22}, {2.83, 3.44}, {2.98, 3.67}};

// How the flume's walls hold the liquid back.
enum class Walls {
  XsphFriction,  // XSPH wall friction 0.1, XSPH viscosity 0.01 between particles
  WallLaw,       // water's viscosity (Morris 1997) with Spalding's law of the wall, no friction knob
};

// The surge front Z at each of Martin & Moyce's sample times, in the flume
// of Martin & Moyce with the given pressure solver.
std::vector<double> surge_front(PressureSolverMethod method, Walls walls) {
  const double a = 2.25 * 0.0254;  // m
  const int n = 16;                // particles across the column's width
  const int depth = 6;             // layers between the side walls
  const float s = static_cast<float>(a / n);
  const float gap = 1.2f * s;  // liquid to wall, see hydrostatic_test.cpp
  SimulationSetup setup;
  setup.particle_spacing = s;
  setup.pressure.method = method;
  setup.liquid.xsph_epsilon = 0.01f;
  if (walls == Walls::XsphFriction) {
    // The flume's walls are no-slip; XSPH wall friction stands in for that.
    // The front is sensitive to it (worst error over the 13 samples, measured
    // 2026-11-22: friction 0.05: 9.5 %, 0.1: 8.3 %, 0.2: 7.3 %, 0.3: 17 %,
    // 0: 14.5 %, the front then leads the experiment throughout, as slip walls do).
    setup.liquid.boundary_friction = 0.1f;
  } else {
    setup.liquid.boundary_friction = 0.0f;
    setup.liquid.kinematic_viscosity = 1e-6f;
    setup.liquid.wall_shear = WallShear::Spalding1961;
  }
  const float lx = static_cast<float>(5.0 * a), ly = static_cast<float>(2.5 * a);
  const float lz = (depth - 1) * s + 2 * gap;
  setup.rigid_position = test::open_tank(lx, ly, lz, s);
  test::add_block(setup, Vec3{gap, gap, gap}, n, 2 * n, depth);
  setup.domain_min = Vec3{-0.05f, -0.05f, -0.05f};
  setup.domain_max = Vec3{lx + 0.05f, ly + 0.2f, lz + 0.05f};
  auto sim = make_simulation(ExecutionConfig{Device::Cpu, 0}, setup);

  // x is measured from the liquid's boundary at the back wall: the first
  // particle's centre lies half a spacing inside it.
  const double back = gap - 0.5 * s;
  const double time_scale = std::sqrt(a / (2 * 9.81));
  std::vector<double> fronts;
  std::int64_t steps = 0;
  for (const Sample& m : kMartinMoyce) {
    sim->advance_to(m.T * time_scale, [&](const StepReport&) { ++steps; });
    ParticleSnapshot p = sim->particles();
    float front = 0;
    int outside = 0;
    for (const Vec3& x : p.position) {
      front = std::max(front, x.x);
      outside += x.x <= 0 || x.x >= lx || x.y <= 0 || x.z <= 0 || x.z >= lz;
    }
    EXPECT_EQ(outside, 0) << "particles through a wall at T = " << m.T;
    fronts.push_back((front + 0.5 * s - back) / a);
  }
  ::testing::Test::RecordProperty("steps", std::to_string(steps));
  return fronts;
}

// Each sample within 10 % of the experiment; the worst is recorded.
void check_surge_front_follows_martin_moyce(PressureSolverMethod method) {
  const std::vector<double> Z = surge_front(method, Walls::XsphFriction);
  double worst = 0;
  for (std::size_t k = 0; k < Z.size(); ++k) {
    const Sample& m = kMartinMoyce[k];
    worst = std::max(worst, std::fabs(Z[k] - m.Z) / m.Z);
    EXPECT_NEAR(Z[k], m.Z, 0.1 * m.Z) << "T = " << m.T;
  }
  ::testing::Test::RecordProperty("worst_relative_front_error", std::to_string(worst));
}

TEST(DamBreak, SurgeFrontFollowsMartinMoyce1952) { check_surge_front_follows_martin_moyce(PressureSolverMethod::Pcisph); }

// The same flume and settings with divergence-free SPH at its own steps.
TEST(DamBreak, DfsphSurgeFrontFollowsMartinMoyce1952) { check_surge_front_follows_martin_moyce(PressureSolverMethod::Dfsph); }

// Least-squares slope of Z over T for the samples from T = 1.9 on.
double late_front_speed(const std::vector<double>& Z) {
  double st = 0, sz = 0, stt = 0, stz = 0, count = 0;
  for (std::size_t k = 0; k < Z.size(); ++k) {
    const double T = kMartinMoyce[k].T;
    if (T < 1.9) continue;
    st += T, sz += Z[k], stt += T * T, stz += T * Z[k], ++count;
  }
  return (count * stz - st * sz) / (count * stt - st * st);
}

// With physical constants only (water's viscosity, Spalding's law of the
// wall with its universal kappa and B, no friction knob): once the front
// runs over the floor (T >= 1.9, 8 samples), what holds it back is the
// wall's shear, and the front's speed dZ/dT follows the experiment's within
// 10 % (measured 2026-12-06: -0.7 %; +3.7 and +0.8 % at 24 and 32
// particles). Its position leads by 6-14 %, a lead set before T = 1.2,
// while the column is released, and not changed by the wall: the
// experiment's release is not modelled (docs/paper-map.md, departures).
TEST(DamBreak, WallLawFrontSpeedFollowsMartinMoyce1952) {
  const std::vector<double> Z = surge_front(PressureSolverMethod::Pcisph, Walls::WallLaw);
  std::vector<double> experiment;
  for (const Sample& m : kMartinMoyce) experiment.push_back(m.Z);
  const double speed = late_front_speed(Z), measured = late_front_speed(experiment);
  ::testing::Test::RecordProperty("front_speed", std::to_string(speed));
  ::testing::Test::RecordProperty("experiment_front_speed", std::to_string(measured));
  EXPECT_NEAR(speed, measured, 0.1 * measured);
}

}  // namespace
}  // namespace dp
