// Vapor mass (paper Sec. 6, DESIGN §6): the conservative transport keeps a
// closed box's vapor to rounding over 1000 full air steps in a random flow,
// and with inflows and open faces the ledger accounts for every kilogram.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "air_test_setups.h"

namespace dp {
namespace {

// A Gaussian blob of vapor on top of the ambient value.
std::vector<double> vapor_blob(const MacGrid& g, Vec3 c, float radius, double peak, double ambient) {
  std::vector<double> rho(g.cell_count());
  for (int k = 0; k < g.nz; ++k)
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const float r2 = length_squared(g.cell_center(i, j, k) - c);
        rho[g.cell(i, j, k)] = ambient + peak * std::exp(-r2 / (radius * radius));
      }
  return rho;
}

TEST(air_VaporMass, ClosedBoxRandomFlowDriftsBelow1e9Over1000Steps) {
  CpuExec exec = test::air_exec();
  AirSettings s = test::quiet_air_box(12, 0.48f);
  // Every part of the step takes part: buoyancy from vapor and heat,
  // confinement, diffusion.
  s.buoyancy_alpha = -3.09f;
  s.buoyancy_beta = 0.0335f;
  s.vorticity_epsilon = 2.0f;
  s.vapor_diffusivity = 2.5e-5f;
  s.heat_diffusivity = 2.2e-5f;
  s.ambient_vapor = 0.008;
  test::SortedParticles none(exec, {}, s.domain_min, s.domain_max, 0.1f);
  AirGrid<CpuExec> air(exec, s, Vec3{0, -9.81f, 0}, none.view());
  AirSnapshot state = air.snapshot();
  test::randomise_velocity(state, 0.5f, 3);
  std::vector<float> t(state.temperature.size());
  for (std::size_t c = 0; c < t.size(); ++c) t[c] = 293.15f + 5.0f * std::sin(0.37f * c);
  air.set_velocity(state.u, state.v, state.w);
  air.set_temperature(t);
  air.set_vapor(exec, vapor_blob(state.grid, Vec3{0.2f, 0.17f, 0.25f}, 0.08f, 0.01, s.ambient_vapor));
  air.project(exec);
  const double m0 = air.vapor_mass(exec);
  const std::vector<double> start = air.snapshot().vapor;
  int substeps = 0;
  for (int step = 0; step < 1000; ++step) substeps = std::max(substeps, air.step(exec, 0.01f).advection_substeps);
  const double drift = std::fabs(air.vapor_mass(exec) - m0) / m0;
  RecordProperty("relative_drift", test::sci(drift));
  EXPECT_LE(drift, 1e-9);
  const AirSnapshot end = air.snapshot();
  EXPECT_GE(*std::min_element(end.vapor.begin(), end.vapor.end()), 0.0) << "transport must keep vapor non-negative";
  // The blob must actually have been moved and mixed for the test to bite.
  double moved = 0;
  for (std::size_t c = 0; c < start.size(); ++c) moved += std::fabs(end.vapor[c] - start[c]);
  EXPECT_GT(moved * end.grid.cell_volume(), 0.1 * (m0 - s.ambient_vapor * end.grid.cell_count() * end.grid.cell_volume()));
  EXPECT_GT(substeps, 0);
}

TEST(air_VaporMass, InflowAndOpenFacesBalanceTheLedgerTo1e9) {
  CpuExec exec = test::air_exec();
  AirSettings s = test::quiet_air_box(16, 0.64f);
  s.ambient_vapor = 0.004;
  s.vapor_diffusivity = 2.5e-5f;
  s.open_face[static_cast<int>(AirFace::XMax)] = true;
  s.open_face[static_cast<int>(AirFace::YMax)] = true;
  AirInflow humid;
  humid.shape = AirInflow::Shape::Disc;
  humid.center = Vec3{0.08f, 0.32f, 0.32f};
  humid.normal = Vec3{1, 0, 0};
  humid.radius = 0.12f;
  humid.thickness = 0.08f;
  humid.velocity = Vec3{1.5f, 0, 0};
  humid.vapor = 0.015;
  s.inflows.push_back(humid);
  test::SortedParticles none(exec, {}, s.domain_min, s.domain_max, 0.1f);
  AirGrid<CpuExec> air(exec, s, Vec3{0, -9.81f, 0}, none.view());
  for (int step = 0; step < 300; ++step) air.step(exec, 0.01f);
  const AirLedger& l = air.ledger();
  const double m = air.vapor_mass(exec);
  RecordProperty("inflow_gain_kg", test::sci(l.inflow_gain));
  RecordProperty("open_out_kg", test::sci(l.open_out));
  RecordProperty("ledger_residual", test::sci(std::fabs(m - l.expected_mass()) / m));
  // Something must actually have come in and gone out for the test to bite.
  EXPECT_GT(l.inflow_gain, 0.05 * l.initial);
  EXPECT_GT(l.open_out, 0.05 * l.initial);
  EXPECT_GT(l.open_in, 0.0);
  EXPECT_LE(std::fabs(m - l.expected_mass()) / m, 1e-9);
}

// Positivity at the sub-step bound: vapor in isolated cells and in runs that
// rise along the flow (the limited slope's worst case, a face value 1.5 times
// its upwind cell's) in a fast random flow, no diffusion to smooth it. The
// transport must never leave a cell below zero; the sub-step count shows the
// bound was what held it there.
TEST(air_VaporMass, SharpVaporInFastFlowStaysNonNegative) {
  CpuExec exec = test::air_exec();
  AirSettings s = test::quiet_air_box(16, 0.32f);  // dx = 0.02 m
  test::SortedParticles none(exec, {}, s.domain_min, s.domain_max, 0.1f);
  AirGrid<CpuExec> air(exec, s, Vec3{0, -9.81f, 0}, none.view());
  AirSnapshot state = air.snapshot();
  test::randomise_velocity(state, 4.0f, 9);
  air.set_velocity(state.u, state.v, state.w);
  air.project(exec);
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> rho(state.grid.cell_count(), 0.0);
  for (std::size_t c = 0; c < rho.size(); ++c) {
    const double r = u(rng);
    rho[c] = r < 0.3 ? 0.0 : (r < 0.6 ? 0.02 * u(rng) : 0.01 * (c % 7));
  }
  air.set_vapor(exec, rho);
  int substeps = 0;
  double lowest = 0;
  for (int step = 0; step < 50; ++step) {
    substeps = std::max(substeps, air.transport_vapor(exec, 0.02f));
    const std::vector<double> v = air.snapshot().vapor;
    lowest = std::min(lowest, *std::min_element(v.begin(), v.end()));
  }
  EXPECT_GE(lowest, 0.0);
  EXPECT_GT(substeps, 1);
}

}  // namespace
}  // namespace dp
