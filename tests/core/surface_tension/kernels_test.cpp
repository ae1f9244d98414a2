// Akinci 2013 cohesion and adhesion kernels against their closed forms, and
// the pair forces' symmetry: equal and opposite forces, so the liquid's
// momentum cannot change through surface tension, also with adaptive masses.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>

#include "mini_sph.h"
#include "sph/surface_tension_akinci2013.h"

namespace dp {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr float kH = 0.02f;  // support radius of 1 cm spacing

// The cohesion kernel in the dimensionless q = r/h, as h^3 C = 32/pi c(q).
double cohesion_shape(double q) {
  if (q <= 0.0 || q > 1.0) return 0.0;
  double bump = std::pow(q * (1.0 - q), 3);
  return q > 0.5 ? bump : 2.0 * bump - 1.0 / 64.0;
}
double cohesion_reference(double r, double h) { return 32.0 / (kPi * h * h * h) * cohesion_shape(r / h); }

// The adhesion kernel in q = r/h: h^3 A = 0.007 (-4q^2 + 6q - 2)^(1/4).
double adhesion_reference(double r, double h) {
  double q = r / h;
  if (q <= 0.5 || q > 1.0) return 0.0;
  return 0.007 / (h * h * h) * std::pow(-4.0 * q * q + 6.0 * q - 2.0, 0.25);
}

// Root of 2 (h - r)^3 r^3 = h^6 / 64 below h/2: r (h - r) = h^2 / 128^(1/3).
double cohesion_zero_crossing(double h) { return h * (0.5 - std::sqrt(0.25 - 1.0 / std::cbrt(128.0))); }

TEST(surface_tension_kernels, CohesionMatchesClosedFormOnBothBranches) {
  const auto c = AkinciCohesionKernel::with_support(kH);
  for (double q : {0.05, 0.1, 0.2, 0.3, 0.4, 0.45, 0.5, 0.55, 0.6, 0.75, 0.9, 0.99, 1.0}) {
    double r = q * kH, expected = cohesion_reference(r, kH);
    EXPECT_NEAR(c.C(static_cast<float>(r)), expected, 2e-5 * (1.0 / (kH * kH * kH)) + 1e-5 * std::fabs(expected))
        << "q = " << q;
  }
}

TEST(surface_tension_kernels, CohesionIsContinuousAtHalfSupportAndZeroOutside) {
  const auto c = AkinciCohesionKernel::with_support(kH);
  // Both branches give h^6/64 at r = h/2, so C(h/2) = 1 / (2 pi h^3).
  const double at_half = 1.0 / (2.0 * kPi * kH * kH * kH);
  EXPECT_NEAR(c.C(0.5f * kH), at_half, 1e-5 * at_half);
  EXPECT_NEAR(c.C(0.5f * kH * (1 - 1e-4f)), c.C(0.5f * kH * (1 + 1e-4f)), 1e-3 * at_half);
  EXPECT_EQ(c.C(kH * 1.0001f), 0.0f);
  EXPECT_EQ(c.C(2.0f * kH), 0.0f);
  EXPECT_NEAR(c.C(kH), 0.0f, 1e-6 * at_half);
  EXPECT_EQ(c.C(0.0f), 0.0f) << "no direction, no force";
}

TEST(surface_tension_kernels, CohesionRepelsBelowItsRootAndAttractsAbove) {
  const auto c = AkinciCohesionKernel::with_support(kH);
  const double r0 = cohesion_zero_crossing(kH);
  EXPECT_NEAR(r0 / kH, 0.27291, 1e-4);
  EXPECT_NEAR(cohesion_shape(r0 / kH), 0.0, 1e-15);
  EXPECT_LT(c.C(static_cast<float>(r0 * 0.999)), 0.0f);
  EXPECT_GT(c.C(static_cast<float>(r0 * 1.001)), 0.0f);
  for (int k = 1; k < 100; ++k) {
    float r = kH * k / 100.0f;
    if (std::fabs(r - r0) < 1e-3 * kH) continue;
    if (r < r0) {
      EXPECT_LT(c.C(r), 0.0f) << "repulsive at r/h = " << r / kH;
    } else {
      EXPECT_GT(c.C(r), 0.0f) << "attractive at r/h = " << r / kH;
    }
  }
  // The repulsion tends to -1 / (2 pi h^3) as particles coincide.
  EXPECT_NEAR(c.C(1e-4f * kH), -1.0 / (2.0 * kPi * kH * kH * kH), 1e-3 / (kH * kH * kH));
}

TEST(surface_tension_kernels, AdhesionMatchesClosedForm) {
  const auto a = AkinciAdhesionKernel::with_support(kH);
  const double peak = 0.007 / std::pow(kH, 3.25) * std::pow(kH / 4.0, 0.25);
  for (double q : {0.0, 0.2, 0.5, 0.51, 0.6, 0.7, 0.75, 0.8, 0.9, 0.99, 1.0, 1.2}) {
    double r = q * kH;
    EXPECT_NEAR(a.A(static_cast<float>(r)), adhesion_reference(r, kH), 1e-5 * peak) << "q = " << q;
  }
}

TEST(surface_tension_kernels, AdhesionVanishesAtBothEndsAndPeaksAtThreeQuarters) {
  const auto a = AkinciAdhesionKernel::with_support(kH);
  const double peak = 0.007 / std::pow(kH, 3.25) * std::pow(kH / 4.0, 0.25);
  EXPECT_EQ(a.A(0.5f * kH), 0.0f);
  EXPECT_NEAR(a.A(kH), 0.0f, 1e-6 * peak);
  EXPECT_EQ(a.A(0.3f * kH), 0.0f);
  EXPECT_EQ(a.A(1.01f * kH), 0.0f);
  EXPECT_NEAR(a.A(0.75f * kH), peak, 1e-5 * peak);
  for (float dq : {0.01f, 0.05f, 0.2f}) {
    EXPECT_LT(a.A((0.75f - dq) * kH), a.A(0.75f * kH));
    EXPECT_LT(a.A((0.75f + dq) * kH), a.A(0.75f * kH));
  }
}

test::MiniSphParameters unit_parameters() {
  test::MiniSphParameters p;
  p.tension = 1.0f;
  return p;
}

TEST(surface_tension_pair, EqualParticlesPullEachOtherEquallyAndOppositely) {
  const auto p = unit_parameters();
  for (float q : {0.2f, 0.4f, 0.6f, 0.8f}) {
    test::MiniSph sim(p, Vec3{-0.1f, -0.1f, -0.1f}, Vec3{0.1f, 0.1f, 0.1f});
    Vec3 d{0.3f, -0.5f, 0.8f};
    d = (q * kH / length(d)) * d;
    sim.add_liquid(Vec3{0.01f, 0.0f, 0.0f});
    sim.add_liquid(Vec3{0.01f, 0.0f, 0.0f} + d);
    sim.evaluate_surface_tension();
    Vec3 a0 = sim.tension[0], a1 = sim.tension[1];
    EXPECT_NEAR(a0.x, -a1.x, 1e-6f * length(a0));
    EXPECT_NEAR(a0.y, -a1.y, 1e-6f * length(a0));
    EXPECT_NEAR(a0.z, -a1.z, 1e-6f * length(a0));
    // Along the line joining them; inward where C attracts.
    Vec3 x01 = sim.position[1] - sim.position[0];
    EXPECT_NEAR(length(cross(a0, x01)), 0.0f, 1e-4f * length(a0) * length(x01));
    float r0 = static_cast<float>(cohesion_zero_crossing(kH));
    if (q * kH > r0) {
      EXPECT_GT(dot(a0, x01), 0.0f) << "attracts at q = " << q;
    } else {
      EXPECT_LT(dot(a0, x01), 0.0f) << "repels at q = " << q;
    }
  }
}

// A jittered lattice with random masses (adaptive weights down to 0.1).
void add_random_cloud(test::MiniSph& sim, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> jitter(-0.3f, 0.3f), weight(0.1f, 1.0f);
  const float s = sim.parameters().spacing;
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 8; ++j)
      for (int k = 0; k < 7; ++k) {
        Vec3 x{(i + jitter(rng)) * s, (j + jitter(rng)) * s, (k + jitter(rng)) * s};
        sim.add_liquid(x, static_cast<MassUnits>(weight(rng) * kFullParticleUnits));
      }
}

TEST(surface_tension_pair, TotalMomentumChangeIsZeroForRandomMasses) {
  test::MiniSph sim(unit_parameters(), Vec3{-0.05f, -0.05f, -0.05f}, Vec3{0.15f, 0.15f, 0.15f});
  add_random_cloud(sim, 11);
  sim.evaluate_surface_tension();
  double total[3] = {0, 0, 0}, magnitude = 0;
  for (std::size_t i = 0; i < sim.position.size(); ++i) {
    double m = sim.parameters().particle_mass() * weight_of(sim.units[i]);
    for (int k = 0; k < 3; ++k) total[k] += m * sim.tension[i][k];
    magnitude += m * length(sim.tension[i]);
  }
  double residual = std::sqrt(total[0] * total[0] + total[1] * total[1] + total[2] * total[2]) / magnitude;
  std::printf("[ measured ] |sum m_i a_i| / sum |m_i a_i| = %.3e over %zu particles\n", residual, sim.position.size());
  RecordProperty("momentum_residual_relative", std::to_string(residual));
  EXPECT_GT(magnitude, 0.0);
  EXPECT_LT(residual, 1e-5);
}

TEST(surface_tension_normal, PointsIntoTheLiquidAndVanishesInside) {
  test::MiniSph sim(unit_parameters(), Vec3{-0.05f, -0.05f, -0.05f}, Vec3{0.15f, 0.15f, 0.15f});
  const float s = sim.parameters().spacing;
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 7; ++j)
      for (int k = 0; k < 7; ++k) sim.add_liquid(Vec3{i * s, j * s, k * s});
  sim.evaluate_surface_tension();
  const Vec3 centre{3 * s, 3 * s, 3 * s};
  for (std::size_t i = 0; i < sim.position.size(); ++i) {
    Vec3 from_centre = sim.position[i] - centre;
    if (max_abs_component(from_centre) < 1.5f * s) {
      EXPECT_LT(length(sim.normal[i]), 1e-4f) << "interior particle " << i;
    }
    if (max_abs_component(from_centre) > 2.5f * s) {
      EXPECT_LT(dot(sim.normal[i], from_centre), 0.0f) << "surface particle " << i;
      EXPECT_GT(length(sim.normal[i]), 0.2f);
    }
  }
}

TEST(surface_tension_adhesion, PullsTowardsTheBoundaryParticleWithItsClosedForm) {
  auto p = unit_parameters();
  test::MiniSph sim(p, Vec3{-0.1f, -0.1f, -0.1f}, Vec3{0.1f, 0.1f, 0.1f});
  const float beta = 2.5f;
  sim.set_rigid({Vec3{0, 0, 0}}, beta);
  Vec3 d = (0.75f * kH / std::sqrt(3.0f)) * Vec3{1, 1, 1};
  sim.add_liquid(d);
  sim.evaluate_surface_tension();
  // A lone boundary particle has V_b = 1 / W(0).
  double volume = 1.0 / CubicSplineKernel::with_support(kH).W(0.0f);
  double expected = beta * p.rest_density * volume * adhesion_reference(0.75 * kH, kH);
  Vec3 a = sim.tension[0];
  EXPECT_NEAR(length(a), expected, 1e-4 * expected);
  EXPECT_NEAR(dot(normalize(a), normalize(d)), -1.0f, 1e-5f);
}

struct Results {
  std::vector<Vec3> position, normal, tension;
};

Results run_cloud_on_wall(int threads) {
  auto p = unit_parameters();
  p.gravity = Vec3{0, -9.81f, 0};
  test::MiniSph sim(p, Vec3{-0.05f, -0.05f, -0.05f}, Vec3{0.15f, 0.15f, 0.15f}, threads);
  std::vector<Vec3> wall;
  for (int j = -3; j < 12; ++j)
    for (int k = -3; k < 12; ++k) wall.push_back(Vec3{-0.012f, j * 0.01f, k * 0.01f});
  sim.set_rigid(wall, 3.0f);
  add_random_cloud(sim, 5);
  for (int step = 0; step < 20; ++step) sim.step(p.time_step());
  sim.evaluate_surface_tension();
  return Results{sim.position, sim.normal, sim.tension};
}

template <class T>
bool bitwise_equal(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

TEST(surface_tension_determinism, AccelerationsAreBitIdenticalForOneAndTwoThreads) {
  Results one = run_cloud_on_wall(1), two = run_cloud_on_wall(2);
  EXPECT_TRUE(bitwise_equal(one.position, two.position));
  EXPECT_TRUE(bitwise_equal(one.normal, two.normal));
  EXPECT_TRUE(bitwise_equal(one.tension, two.tension));
}

}  // namespace
}  // namespace dp
