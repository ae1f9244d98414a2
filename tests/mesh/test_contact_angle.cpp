// The wall corrections of paper Sec. 7 on one particle on a floor (paper
// Fig. 3), measured on the mesh: the static angle at the contact line for
// alpha_base = 45, 90, 135 degrees, contact without crossing into the wall,
// and the dynamic angles of a drop moving along the wall.
#include <gtest/gtest.h>

#include <cstdio>

#include "mesh_topology.h"
#include "wall_drop.h"

namespace dp::mesh {
namespace {

constexpr double kDeg = M_PI / 180;

double lowest_y(const SurfaceMesh& mesh) {
  double y = INFINITY;
  for (const Vec3d& p : mesh.position) y = std::min(y, p.y);
  return y;
}

class mesh_StaticContactAngle : public ::testing::TestWithParam<double> {};

TEST_P(mesh_StaticContactAngle, MeshMeetsTheFloorAtAlphaBase) {
  testing::WallDrop drop;
  drop.angles.base = GetParam() * kDeg;
  const SurfaceMesh mesh = drop.mesh();
  ASSERT_FALSE(mesh.triangles.empty());
  EXPECT_EQ(testing::orientation_problem(mesh), "");
  EXPECT_EQ(testing::euler_characteristic(mesh), 2);
  const double measured = testing::contact_angle_deg(mesh, drop);
  EXPECT_NEAR(measured, GetParam(), 5.0);
  std::printf("alpha_base %.0f: measured %.2f degrees\n", GetParam(), measured);
  // Touches the floor (no gap) and never crosses into it.
  EXPECT_GE(lowest_y(mesh), drop.floor_height - 1e-9);
  EXPECT_LT(lowest_y(mesh), drop.floor_height + 1e-3 * drop.radius);
}

INSTANTIATE_TEST_SUITE_P(Angles, mesh_StaticContactAngle, ::testing::Values(45.0, 90.0, 135.0));

TEST(mesh_ContactAngle, UncorrectedDropFloatsAboveTheFloorAsASphere) {
  testing::WallDrop drop;
  drop.height_over_floor = 1.2;  // a free sphere of radius r, 0.2 r above the floor
  const SurfaceMesh mesh = drop.mesh(false);
  EXPECT_NEAR(lowest_y(mesh), drop.floor_height + 0.2 * drop.radius, 0.01 * drop.radius);
}

TEST(mesh_ContactAngle, CorrectionStopsBeyondOneRadiusFromTheWall) {
  // Sec. 7: only where |xbar - xbar_p| < rbar; 1.2 r above the floor the
  // corrected and uncorrected meshes are the same surface.
  testing::WallDrop drop;
  drop.height_over_floor = 1.2;
  drop.angles.base = 45 * kDeg;
  const SurfaceMesh corrected = drop.mesh(true), plain = drop.mesh(false);
  ASSERT_EQ(corrected.position.size(), plain.position.size());
  for (std::size_t v = 0; v < plain.position.size(); ++v)
    ASSERT_NEAR(length(corrected.position[v] - plain.position[v]), 0, 1e-9);
}

// Eq. 22-23 as the paper prints them, averaged over the directions
// (measured from the velocity) of a wedge of the contact line: what the mesh
// should show there.
double expected_wedge_angle_deg(double centre_rad, double half_wedge_rad, double base_deg, double a_deg, double speed) {
  const double advancing = 90 + a_deg * std::cbrt(speed), receding = 90 - a_deg * std::cbrt(speed);
  double sum = 0;
  const int samples = 2000;
  for (int n = 0; n < samples; ++n) {
    const double p = std::cos(centre_rad - half_wedge_rad + 2 * half_wedge_rad * (n + 0.5) / samples);
    sum += p < 0 ? std::pow(p, 4) * receding + (1 - std::pow(p, 4)) * base_deg
                 : std::pow(p, 0.25) * advancing + (1 - std::pow(p, 0.25)) * base_deg;
  }
  return sum / samples;
}

// Paper Fig. 3: a one-particle drop moving along the wall spreads ahead
// (advancing angle) and pulls a narrow tail behind (receding angle).
TEST(mesh_ContactAngle, MovingDropAdvancesSteeperThanStaticAndRecedesFlatter) {
  testing::WallDrop drop;
  drop.angles = {90 * kDeg, 30 * kDeg, 30 * kDeg};
  const double static_angle = testing::contact_angle_deg(drop.mesh(), drop);
  drop.velocity = {0.5, 0, 0};
  const SurfaceMesh moving = drop.mesh();
  EXPECT_EQ(testing::orientation_problem(moving), "");
  const double wedge = 12 * kDeg;
  const double advancing = testing::contact_angle_deg(moving, drop, {1, 0, 0}, wedge);
  const double receding = testing::contact_angle_deg(moving, drop, {-1, 0, 0}, wedge);
  const double side = testing::contact_angle_deg(moving, drop, {0, 0, 1}, wedge);
  EXPECT_NEAR(static_angle, 90, 5);
  EXPECT_GT(advancing, static_angle + 10);
  EXPECT_LT(receding, static_angle - 10);
  // Against Eq. 22-23 over the same wedges: ahead p ~ 1, behind p ~ -1, and
  // at the side p ~ 0, where p^(1/4) already leans towards advancing.
  EXPECT_NEAR(advancing, expected_wedge_angle_deg(0, wedge, 90, 30, 0.5), 5);
  EXPECT_NEAR(receding, expected_wedge_angle_deg(M_PI, wedge, 90, 30, 0.5), 5);
  EXPECT_NEAR(side, expected_wedge_angle_deg(M_PI / 2, wedge, 90, 30, 0.5), 5);
  std::printf("static %.1f, advancing %.1f (Eq. 22-23: %.1f), receding %.1f (%.1f), side %.1f (%.1f) degrees\n",
              static_angle, advancing, expected_wedge_angle_deg(0, wedge, 90, 30, 0.5), receding,
              expected_wedge_angle_deg(M_PI, wedge, 90, 30, 0.5), side,
              expected_wedge_angle_deg(M_PI / 2, wedge, 90, 30, 0.5));
}

}  // namespace
}  // namespace dp::mesh
