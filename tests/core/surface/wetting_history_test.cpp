// The wetting history (paper Sec. 4.3, 6.2): which texels a liquid particle
// touches, and how the record fades once they are dry. References: the
// contact disc's radius from Pythagoras (a particle at height d over the
// plate, contact radius R: sqrt(R^2 - d^2)) and exp(-t / tau).
#include <gtest/gtest.h>

#include <cmath>

#include "backend/cpu_exec.h"
#include "sph/particle_grid.h"
#include "surface/wetting_history_wang2005.h"
#include "surface_scenes.h"

namespace dp {
namespace {

constexpr float kSpacing = 0.01f;

// The liquid particles of one step, sorted into a grid as the step does.
struct LiquidGrid {
  ParticleGrid<CpuExec> grid;
  std::vector<Vec3> position;
  LiquidGrid(const CpuExec& exec, std::vector<Vec3> p) {
    grid.grid.origin = Vec3{-0.1f, -0.1f, -0.1f};
    grid.grid.cell_size = 2 * kSpacing;
    grid.grid.nx = grid.grid.ny = grid.grid.nz = 25;
    std::vector<Vec3> unsorted = p;
    grid.sort(exec, unsorted);
    position.resize(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) position[i] = unsorted[grid.order[i]];
    grid.find_ranges(exec);
  }
  GridView view() const { return grid.view(position); }
};

void record(const CpuExec& exec, const LiquidGrid& liquid, const TexelGeometry& g, float dry, std::vector<float>& wetting) {
  const float r = kWettingContactSpacings * kSpacing;
  std::vector<std::uint8_t> near(liquid.grid.grid.cell_count());
  exec.parallel_for(near.size(), MarkCellsNearLiquid{liquid.view(), near.data()});
  exec.parallel_for(g.size(), RecordWetting{liquid.view(), near.data(), g.position.data(), g.normal.data(), r, dry, wetting.data()});
}

TEST(WettingHistory, AParticleWetsTheDiscUnderItOnTheFrontSideOnly) {
  CpuExec exec(2);
  const TexelGeometry g = test::lattice_texels(81, 0.0025f, 0.0f);  // 0.2 m plate, 2.5 mm texels
  const Vec3 above{0.1f, kSpacing, 0.1f}, below{0.05f, -kSpacing, 0.05f};
  LiquidGrid liquid(exec, {above, below});
  std::vector<float> wetting(g.size(), 0.0f);
  record(exec, liquid, g, 0.5f, wetting);
  const float R = kWettingContactSpacings * kSpacing;
  const float disc = std::sqrt(R * R - kSpacing * kSpacing);  // = one spacing
  int wet = 0;
  for (std::size_t t = 0; t < g.size(); ++t) {
    const Vec3 d = g.position[t] - Vec3{above.x, 0, above.z};
    const float r = length(d);
    if (r < 0.98f * disc) {
      EXPECT_EQ(wetting[t], 1.0f) << "texel " << t << " at " << r << " m";
    }
    if (r > 1.02f * disc) {
      EXPECT_EQ(wetting[t], 0.0f) << "texel " << t << " at " << r << " m";  // `below` wets nothing
    }
    wet += wetting[t] == 1.0f;
  }
  EXPECT_GT(wet, 40);  // pi (4 texels)^2 ~ 50
}

TEST(WettingHistory, DryTexelsFadeExponentially) {
  CpuExec exec(2);
  const TexelGeometry g = test::lattice_texels(5, 0.0025f, 0.0f);  // all within 7.1 mm of the particle's foot
  LiquidGrid wet_step(exec, {Vec3{0.005f, 0.3f * kSpacing, 0.005f}});
  LiquidGrid dry_step(exec, {Vec3{0.15f, 0.15f, 0.15f}});
  std::vector<float> wetting(g.size(), 0.0f);
  record(exec, wet_step, g, 0.0f, wetting);
  for (float w : wetting) ASSERT_EQ(w, 1.0f);
  const float dt = 0.02f, tau = 0.5f;
  const int steps = 20;
  for (int k = 0; k < steps; ++k) record(exec, dry_step, g, std::exp(-dt / tau), wetting);
  const double expected = std::exp(-steps * dt / tau);
  for (float w : wetting) EXPECT_NEAR(w, expected, 1e-5 * steps * expected);
}

TEST(WettingHistory, ThroughTheSimulationAParticleAtRestKeepsItsTrailWet) {
  SimulationSetup setup = test::plate_setup(kSpacing);
  setup.rigid_position = test::plate_particles(0.2f, 0.0f, kSpacing);
  SurfaceTextureSetup s;
  s.rigid_count = setup.rigid_position.size();
  s.texels = test::lattice_texels(41, 0.005f, 0.0f);
  s.wetting_decay = 0.1f;
  setup.surfaces.push_back(s);
  setup.liquid_position = {Vec3{0.1f, kSpacing, 0.1f}};
  setup.liquid_velocity = {Vec3{}};
  auto sim = make_simulation(ExecutionConfig{Device::Cpu, 2}, setup);
  const SurfaceSnapshot before = sim->surfaces().at(0);
  for (float w : before.wetting) ASSERT_EQ(w, 0.0f);  // nothing recorded before a step
  sim->step();
  const SurfaceSnapshot snap = sim->surfaces().at(0);
  const std::size_t centre = 20 * 41 + 20;  // texel at (0.1, 0, 0.1)
  EXPECT_EQ(snap.wetting[centre], 1.0f);
  EXPECT_EQ(snap.wetting[0], 0.0f);
}

}  // namespace
}  // namespace dp
