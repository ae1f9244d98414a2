// Diffusion (Alg. 1 line 10): a point blob spreading with coefficient D has
// per-axis variance growing as 2 D t (the heat kernel's), mass constant.
#include <gtest/gtest.h>

#include "air_test_setups.h"

namespace dp {
namespace {

struct Moments {
  double mass = 0;
  double variance[3] = {0, 0, 0};
};

// Mass above the background, and per axis the variance of its distribution.
template <class T>
Moments moments(const MacGrid& g, const std::vector<T>& f, double background) {
  Moments m;
  double mean[3] = {0, 0, 0};
  auto each_cell = [&](auto visit) {
    for (int k = 0; k < g.nz; ++k)
      for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i) visit(static_cast<double>(f[g.cell(i, j, k)]) - background, g.cell_center(i, j, k));
  };
  each_cell([&](double w, Vec3 x) {
    m.mass += w;
    for (int a = 0; a < 3; ++a) mean[a] += w * x[a];
  });
  for (double& c : mean) c /= m.mass;
  each_cell([&](double w, Vec3 x) {
    for (int a = 0; a < 3; ++a) m.variance[a] += w * (x[a] - mean[a]) * (x[a] - mean[a]);
  });
  for (double& v : m.variance) v /= m.mass;
  return m;
}

TEST(air_Diffusion, PointBlobVarianceGrowsAsTwoDtPerAxis) {
  CpuExec exec = test::air_exec();
  AirSettings s = test::quiet_air_box(41, 0.41f);  // dx = 1 cm, centre cell (20, 20, 20)
  s.vapor_diffusivity = 2.5e-5f;
  s.heat_diffusivity = 2.2e-5f;
  test::SortedParticles none(exec, {}, s.domain_min, s.domain_max, 0.1f);
  AirGrid<CpuExec> air(exec, s, Vec3{0, -9.81f, 0}, none.view());
  const MacGrid& g = air.grid();
  std::vector<double> rho(g.cell_count(), 0.001);
  std::vector<float> t(g.cell_count(), 290.0f);
  rho[g.cell(20, 20, 20)] += 1.0;
  t[g.cell(20, 20, 20)] += 100.0f;
  air.set_vapor(exec, rho);
  air.set_temperature(t);
  const Moments v0 = moments(g, rho, 0.001), t0 = moments(g, t, 290.0);
  const float dt = 0.5f;
  const int steps = 40;  // 20 s: sigma = sqrt(2 D t) ~ 3 cells, far from the walls
  int substeps = 0;
  for (int n = 0; n < steps; ++n) substeps += air.diffuse(exec, dt);
  const AirSnapshot end = air.snapshot();
  const Moments v1 = moments(g, end.vapor, 0.001), t1 = moments(g, end.temperature, 290.0);
  const double time = steps * dt;
  for (int a = 0; a < 3; ++a) {
    const double expected_vapor = 2.0 * s.vapor_diffusivity * time, expected_heat = 2.0 * s.heat_diffusivity * time;
    EXPECT_NEAR(v1.variance[a] - v0.variance[a], expected_vapor, 0.02 * expected_vapor) << "axis " << a;
    EXPECT_NEAR(t1.variance[a] - t0.variance[a], expected_heat, 0.02 * expected_heat) << "axis " << a;
  }
  EXPECT_NEAR(v1.mass, v0.mass, 1e-12 * v0.mass);
  EXPECT_GE(substeps, steps);
}

}  // namespace
}  // namespace dp
