// Surface tension shapes a weightless liquid: blocks relax towards spheres
// and stay together, and their motion dies down under viscosity.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "mini_sph.h"

namespace dp {
namespace {

using Matrix3 = std::array<std::array<double, 3>, 3>;

// Eigenvalues of a symmetric 3x3 matrix by cyclic Jacobi rotations; the
// tests need only the principal moments, and the core builds without Eigen.
std::array<double, 3> symmetric_eigenvalues(Matrix3 a) {
  for (int sweep = 0; sweep < 50; ++sweep) {
    double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    if (off < 1e-30 * (a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2])) break;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q) {
        if (a[p][q] == 0.0) continue;
        double theta = 0.5 * (a[q][q] - a[p][p]) / a[p][q];
        double t = (theta >= 0 ? 1.0 : -1.0) / (std::fabs(theta) + std::sqrt(theta * theta + 1.0));
        double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
        for (int k = 0; k < 3; ++k) {  // a <- a J
          double akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (int k = 0; k < 3; ++k) {  // a <- J^T a
          double apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
      }
  }
  return {a[0][0], a[1][1], a[2][2]};
}

struct Shape {
  double axis_ratio;      // largest / smallest principal semi-axis
  double reach_ratio;     // farthest particle / radius of gyration
  double farthest;        // m, from the centre of mass
  double gyration;        // m
};

// Principal semi-axes are proportional to the square roots of the
// positions' covariance eigenvalues. A cube's covariance is isotropic, so
// the reach ratio tells cube (sqrt(3) for a solid one) from ball (sqrt(5/3)).
Shape shape_of(const test::MiniSph& sim) {
  const Vec3 c = sim.centre_of_mass();
  Matrix3 cov{};
  double farthest2 = 0, sum_r2 = 0;
  for (Vec3 x : sim.position) {
    Vec3 d = x - c;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) cov[a][b] += static_cast<double>(d[a]) * d[b];
    double r2 = length_squared(d);
    farthest2 = std::max(farthest2, r2);
    sum_r2 += r2;
  }
  std::array<double, 3> ev = symmetric_eigenvalues(cov);
  std::sort(ev.begin(), ev.end());
  double gyration = std::sqrt(sum_r2 / sim.position.size());
  return Shape{std::sqrt(ev[2] / ev[0]), std::sqrt(farthest2) / gyration, std::sqrt(farthest2), gyration};
}

test::MiniSphParameters weightless_liquid() {
  test::MiniSphParameters p;
  p.tension = 1.0f;  // strong, so the test relaxes within a fraction of a second
  p.viscosity_alpha = 0.1f;
  return p;
}

void add_block(test::MiniSph& sim, int nx, int ny, int nz) {
  const float s = sim.parameters().spacing;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k)
        sim.add_liquid(Vec3{(i - 0.5f * (nx - 1)) * s, (j - 0.5f * (ny - 1)) * s, (k - 0.5f * (nz - 1)) * s});
}

struct Relaxation {
  Shape initial, final;
  double peak_kinetic_energy = 0, final_kinetic_energy = 0;
  double farthest_ever = 0;  // m, largest distance of any particle from the centre of mass
  double late_axis_ratio = 0;  // largest axis ratio over the last quarter of the run
};

Relaxation relax(test::MiniSph& sim, float duration) {
  Relaxation r;
  r.initial = shape_of(sim);
  const float dt = sim.parameters().time_step();
  const int steps = static_cast<int>(duration / dt);
  for (int n = 0; n < steps; ++n) {
    sim.step(dt);
    r.peak_kinetic_energy = std::max(r.peak_kinetic_energy, sim.kinetic_energy());
    if (n % 25 != 0) continue;
    Shape now = shape_of(sim);
    r.farthest_ever = std::max(r.farthest_ever, now.farthest);
    if (4 * n >= 3 * steps) r.late_axis_ratio = std::max(r.late_axis_ratio, now.axis_ratio);
  }
  r.final = shape_of(sim);
  r.final_kinetic_energy = sim.kinetic_energy();
  return r;
}

void report(const char* name, const Relaxation& r) {
  std::printf("[ measured ] %s: axis ratio %.3f -> %.3f (at most %.3f over the last quarter), reach ratio %.3f -> "
              "%.3f, kinetic energy peak %.3e J, final %.3e J, farthest particle ever %.4f m (radius of gyration "
              "%.4f m)\n",
              name, r.initial.axis_ratio, r.final.axis_ratio, r.late_axis_ratio, r.initial.reach_ratio,
              r.final.reach_ratio, r.peak_kinetic_energy, r.final_kinetic_energy, r.farthest_ever, r.final.gyration);
  ::testing::Test::RecordProperty("axis_ratio", std::to_string(r.final.axis_ratio));
  ::testing::Test::RecordProperty("reach_ratio", std::to_string(r.final.reach_ratio));
  ::testing::Test::RecordProperty("kinetic_energy_final_over_peak",
                                  std::to_string(r.final_kinetic_energy / r.peak_kinetic_energy));
}

// A particle that left the liquid would fly on; one that stays never gets
// much farther from the centre than the block's corners were.
void expect_nothing_escaped(const Relaxation& r, const test::MiniSph& sim) {
  EXPECT_LT(r.farthest_ever, r.initial.farthest + sim.parameters().support_radius());
}

TEST(surface_tension_physics, CubeRelaxesTowardsASphereAndStaysTogether) {
  test::MiniSph sim(weightless_liquid(), Vec3{-0.15f, -0.15f, -0.15f}, Vec3{0.15f, 0.15f, 0.15f});
  add_block(sim, 10, 10, 10);
  Relaxation r = relax(sim, 0.4f);
  report("cube 10^3", r);
  EXPECT_NEAR(r.initial.reach_ratio, 1.567, 0.01) << "corners of a 10^3 lattice";
  EXPECT_LT(r.final.reach_ratio, 1.33) << "corners pulled in (a solid ball has 1.29)";
  EXPECT_LT(r.late_axis_ratio, 1.1);
  expect_nothing_escaped(r, sim);
  EXPECT_LT(r.final_kinetic_energy, 0.1 * r.peak_kinetic_energy);
}

TEST(surface_tension_physics, ElongatedBlockRelaxesTowardsASphere) {
  test::MiniSph sim(weightless_liquid(), Vec3{-0.15f, -0.15f, -0.15f}, Vec3{0.15f, 0.15f, 0.15f});
  add_block(sim, 12, 6, 6);
  Relaxation r = relax(sim, 0.8f);
  report("block 12x6x6", r);
  EXPECT_GT(r.initial.axis_ratio, 1.9);
  EXPECT_LT(r.late_axis_ratio, 1.1);
  expect_nothing_escaped(r, sim);
  EXPECT_LT(r.final_kinetic_energy, 0.1 * r.peak_kinetic_energy);
}

}  // namespace
}  // namespace dp
