// Buoyancy (paper Eq. 5, Fedkiw et al. 2001): a hot blob rises and a cold
// one sinks; vapor-laden air rises for alpha < 0 and sinks for alpha > 0; a
// mirror-symmetric setup stays mirror-symmetric.
#include <gtest/gtest.h>

#include "air_test_setups.h"

namespace dp {
namespace {

struct Blob {
  float temperature_offset;  // K
  double vapor;              // kg/m^3 above ambient
};

// Vertical centre of mass of |T - T_amb| (or of vapor) after `steps`.
struct Rise {
  double start, end;
};

AirSettings buoyant_box() {
  AirSettings s = test::quiet_air_box(24, 0.48f);
  s.buoyancy_alpha = -3.09f;
  s.buoyancy_beta = 0.0335f;
  s.ambient_temperature = 293.15f;
  s.ambient_vapor = 0;
  return s;
}

Rise blob_rise(AirSettings s, Blob b, int steps, bool weigh_vapor) {
  CpuExec exec = test::air_exec();
  test::SortedParticles none(exec, {}, s.domain_min, s.domain_max, 0.1f);
  AirGrid<CpuExec> air(exec, s, Vec3{0, -9.81f, 0}, none.view());
  const MacGrid& g = air.grid();
  std::vector<float> t(g.cell_count(), s.ambient_temperature);
  std::vector<double> rho(g.cell_count(), 0.0);
  const Vec3 c{0.24f, 0.24f, 0.24f};
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const float r2 = length_squared(g.cell_center(i, j, k) - c);
        const float shape = std::exp(-r2 / (0.06f * 0.06f));
        t[g.cell(i, j, k)] += b.temperature_offset * shape;
        rho[g.cell(i, j, k)] = b.vapor * shape;
      }
  air.set_temperature(t);
  air.set_vapor(exec, rho);
  auto height = [&](const AirSnapshot& a) {
    double w = 0, wy = 0;
    for (int k = 0; k < g.nz; ++k)
      for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i) {
          const std::size_t n = g.cell(i, j, k);
          const double m = weigh_vapor ? a.vapor[n] : std::fabs(a.temperature[n] - s.ambient_temperature);
          w += m;
          wy += m * g.cell_center(i, j, k).y;
        }
    return wy / w;
  };
  Rise r;
  r.start = height(air.snapshot());
  for (int n = 0; n < steps; ++n) air.step(exec, 0.01f);
  r.end = height(air.snapshot());
  return r;
}

TEST(air_Buoyancy, HotBlobRisesColdBlobSinks) {
  const Rise hot = blob_rise(buoyant_box(), Blob{20.0f, 0.0}, 60, false);
  const Rise cold = blob_rise(buoyant_box(), Blob{-20.0f, 0.0}, 60, false);
  // The blob is accelerated by beta dT ~ 0.67 m/s^2 at its centre: over 0.6 s
  // it moves centimetres; a cell is 2 cm.
  EXPECT_GT(hot.end - hot.start, 0.01);
  EXPECT_LT(cold.end - cold.start, -0.01);
}

TEST(air_Buoyancy, HumidAirRisesForNegativeAlphaSinksForPositive) {
  AirSettings s = buoyant_box();
  const Rise humid = blob_rise(s, Blob{0.0f, 0.2}, 60, true);
  s.buoyancy_alpha = 3.09f;
  const Rise smoke = blob_rise(s, Blob{0.0f, 0.2}, 60, true);
  EXPECT_GT(humid.end - humid.start, 0.005);
  EXPECT_LT(smoke.end - smoke.start, -0.005);
}

// Two hot blobs mirrored across the plane x = L/2, with vorticity
// confinement: temperature and velocity stay mirror images to 1e-5 of their
// ranges.
TEST(air_Buoyancy, MirrorSymmetricSetupStaysSymmetric) {
  CpuExec exec = test::air_exec();
  AirSettings s = buoyant_box();
  s.vorticity_epsilon = 2.0f;
  s.heat_diffusivity = 2.2e-5f;
  // The solve's residual is itself asymmetric: it must sit well below the
  // symmetry being checked.
  s.projection_tolerance = 1e-6f;
  test::SortedParticles none(exec, {}, s.domain_min, s.domain_max, 0.1f);
  AirGrid<CpuExec> air(exec, s, Vec3{0, -9.81f, 0}, none.view());
  const MacGrid& g = air.grid();
  // One blob at x = 0.15, its mirror image copied (not recomputed, which
  // would round differently) to the other half.
  std::vector<float> t(g.cell_count(), s.ambient_temperature);
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx / 2; ++i) {
        const float r2 = length_squared(g.cell_center(i, j, k) - Vec3{0.15f, 0.15f, 0.2f});
        t[g.cell(i, j, k)] += 15.0f * std::exp(-r2 / 0.003f);
        t[g.cell(g.nx - 1 - i, j, k)] = t[g.cell(i, j, k)];
      }
  air.set_temperature(t);
  for (int n = 0; n < 60; ++n) air.step(exec, 0.01f);
  const AirSnapshot a = air.snapshot();
  double t_range = 0, t_asym = 0, u_range = 0, u_asym = 0;
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const int m = g.nx - 1 - i;
        t_range = std::fmax(t_range, std::fabs(a.temperature[g.cell(i, j, k)] - s.ambient_temperature));
        t_asym = std::fmax(t_asym, std::fabs(a.temperature[g.cell(i, j, k)] - a.temperature[g.cell(m, j, k)]));
        const float vy = a.v[g.face(1, i, j, k)], vy_m = a.v[g.face(1, m, j, k)];
        u_range = std::fmax(u_range, std::fabs(vy));
        u_asym = std::fmax(u_asym, std::fabs(vy - vy_m));
      }
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i <= g.nx; ++i) {
        // u_x is odd under the mirror: u(i) = -u(nx - i).
        const float ux = a.u[g.face(0, i, j, k)], ux_m = a.u[g.face(0, g.nx - i, j, k)];
        u_asym = std::fmax(u_asym, std::fabs(ux + ux_m));
      }
  RecordProperty("temperature_asymmetry", test::sci(t_asym / t_range));
  RecordProperty("velocity_asymmetry", test::sci(u_asym / u_range));
  ASSERT_GT(u_range, 1e-3) << "the blobs should have set the air moving";
  EXPECT_LE(t_asym / t_range, 1e-5);
  EXPECT_LE(u_asym / u_range, 1e-5);
}

}  // namespace
}  // namespace dp
