// The pieces of the wall corrections against references outside the
// mesher: Deserno's meniscus (Eq. 20) against the capillary rise at a wall
// and the Young-Laplace equation; Embree's closest points against the
// closed-form closest point on a box; CGAL's checks on meshes with known
// faults.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "closest_point_triangle.h"
#include "deserno_meniscus.h"
#include "mesh_check.h"
#include "rigid_walls.h"

namespace dp::mesh {
namespace {

constexpr double kDeg = M_PI / 180;

// Rise of a meniscus at a vertical wall, with theta the contact angle
// against the wall: h = l sqrt(2 (1 - sin theta)) (de Gennes, Brochard-Wyart
// & Quere, Capillarity and Wetting Phenomena, 2004, Sec. 2.1). Deserno's
// psi0, measured from the horizontal, is pi/2 - theta.
TEST(mesh_DesernoMeniscus, HeightAtTheWallIsTheCapillaryRise) {
  const double l = 0.003;
  for (double psi0_deg : {-60.0, -30.0, 10.0, 45.0, 80.0}) {
    const double psi0 = psi0_deg * kDeg, theta = M_PI / 2 - psi0;
    const DesernoMeniscus2004 m(psi0, l);
    EXPECT_NEAR(std::abs(m.y(0)), l * std::sqrt(2 * (1 - std::sin(theta))), 1e-12) << psi0_deg;
    EXPECT_EQ(m.x(0), 0.0);
  }
}

// The curve is a meniscus: at the wall it leaves at psi0 to the horizontal,
// and along it the curvature equals height / l^2 (Young-Laplace with the
// hydrostatic pressure).
TEST(mesh_DesernoMeniscus, LeavesTheWallAtPsi0AndObeysYoungLaplace) {
  const double l = 1.0, h = 1e-4;
  for (double psi0_deg : {-45.0, 20.0, 45.0, 70.0}) {
    const DesernoMeniscus2004 m(psi0_deg * kDeg, l);
    const double dx0 = (m.x(h) - m.x(0)) / h, dy0 = (m.y(h) - m.y(0)) / h;
    EXPECT_NEAR(std::atan2(-dy0, dx0), psi0_deg * kDeg, 1e-3) << psi0_deg;
    for (double s : {0.2, 0.7, 1.5, 3.0}) {
      const double xd = (m.x(s + h) - m.x(s - h)) / (2 * h), yd = (m.y(s + h) - m.y(s - h)) / (2 * h);
      const double xdd = (m.x(s + h) - 2 * m.x(s) + m.x(s - h)) / (h * h), ydd = (m.y(s + h) - 2 * m.y(s) + m.y(s - h)) / (h * h);
      const double curvature = (xd * ydd - yd * xdd) / std::pow(xd * xd + yd * yd, 1.5);
      EXPECT_NEAR(curvature, m.y(s) / (l * l), 2e-4) << psi0_deg << " at s " << s;
      EXPECT_NEAR(xd * xd + yd * yd, 1.0, 1e-6) << "s is arc length";
    }
  }
}

TEST(mesh_DesernoMeniscus, HeightAtDistanceInvertsX) {
  const DesernoMeniscus2004 m(50 * kDeg, 0.01);
  for (double s : {0.0, 0.001, 0.004, 0.02, 0.1}) EXPECT_NEAR(m.height_at_distance(m.x(s)), m.y(s), 1e-12) << s;
}

// Closest points on the surface of the box [-1,1] x [-0.5,0.5] x [-2,2]:
// clamping to the box outside; inside, the nearest face.
Vec3d closest_on_box(Vec3d p, Vec3d half) {
  bool inside = true;
  Vec3d q;
  for (int a = 0; a < 3; ++a) {
    q[a] = std::clamp(p[a], -half[a], half[a]);
    inside = inside && std::abs(p[a]) < half[a];
  }
  if (!inside) return q;
  int axis = 0;
  double gap = INFINITY;
  for (int a = 0; a < 3; ++a)
    if (half[a] - std::abs(p[a]) < gap) gap = half[a] - std::abs(p[a]), axis = a;
  q = p;
  q[axis] = p[axis] < 0 ? -half[axis] : half[axis];
  return q;
}

io::TriangleMesh box_mesh(Vec3d half) {
  io::TriangleMesh m;
  for (int c = 0; c < 8; ++c)
    m.positions.push_back({float(c & 1 ? half.x : -half.x), float(c & 2 ? half.y : -half.y), float(c & 4 ? half.z : -half.z)});
  m.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                 {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  m.normals.assign(8, {0, 0, 0});
  return m;
}

TEST(mesh_RigidWalls, EmbreeClosestPointsMatchTheBoxInClosedForm) {
  const Vec3d half{1, 0.5, 2};
  const RigidWalls walls({box_mesh(half)});
  std::mt19937 random(7);
  auto uniform = [&](double a, double b) { return a + (b - a) * double(random()) / double(std::mt19937::max()); };
  for (int n = 0; n < 2000; ++n) {
    const Vec3d p{uniform(-2, 2), uniform(-1.5, 1.5), uniform(-3, 3)};
    const Vec3d expected = closest_on_box(p, half);
    const WallPoint w = walls.closest(p, 10);
    ASSERT_TRUE(w.found);
    ASSERT_NEAR(w.distance, length(p - expected), 1e-9) << p.x << " " << p.y << " " << p.z;
    ASSERT_NEAR(length(w.point - expected), 0, 1e-6);
    ASSERT_EQ(w.rigid, 0);
    // Outward faces: a point outside lies on the normal's side.
    if (std::abs(p.x) > half.x || std::abs(p.y) > half.y || std::abs(p.z) > half.z)
      ASSERT_GE(dot(p - w.point, w.face_normal), -1e-12);
  }
}

TEST(mesh_RigidWalls, NothingBeyondTheSearchRadius) {
  const RigidWalls walls({box_mesh({1, 1, 1})});
  EXPECT_FALSE(walls.closest({3, 0, 0}, 1.99).found);
  EXPECT_TRUE(walls.closest({3, 0, 0}, 2.01).found);
  const RigidWalls none({});
  EXPECT_FALSE(none.closest({0, 0, 0}, 100).found);
}

// A disc of `segments` slivers fanned around its centre (as cylinder caps
// often are), tilted so that no sliver lies along the axes: the triangles
// RigidWalls hands to Embree in pieces.
io::TriangleMesh tilted_fan(int segments) {
  io::TriangleMesh m;
  const double tilt = 0.3;
  auto at = [&](double x, double z) {
    m.positions.push_back({float(x), float(std::sin(tilt) * z), float(std::cos(tilt) * z)});
  };
  at(0, 0);
  for (int s = 0; s < segments; ++s) at(std::cos(2 * M_PI * s / segments), std::sin(2 * M_PI * s / segments));
  for (int s = 0; s < segments; ++s)
    m.triangles.push_back({0u, std::uint32_t(1 + s), std::uint32_t(1 + (s + 1) % segments)});
  m.normals.assign(m.positions.size(), {0, 1, 0});
  return m;
}

// The answer RigidWalls::closest promises, by trying every triangle.
WallPoint closest_by_brute_force(const io::TriangleMesh& m, Vec3d x, double max_distance) {
  WallPoint best;
  best.distance = max_distance;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    Vec3d v[3];
    for (int k = 0; k < 3; ++k) {
      const auto& p = m.positions[m.triangles[t][k]];
      v[k] = {p[0], p[1], p[2]};
    }
    const Vec3d q = closest_point_on_triangle(x, v[0], v[1], v[2]);
    if (length(q - x) < best.distance) best = {true, q, normalized(cross(v[1] - v[0], v[2] - v[0])), length(q - x), 0, unsigned(t)};
  }
  return best;
}

// Embree searches pieces of the fan's slivers and may start from a hint;
// neither may change the answer, bit for bit.
TEST(mesh_RigidWalls, PiecesAndHintsGiveTheBruteForceAnswerOnAFan) {
  const io::TriangleMesh fan = tilted_fan(360);
  const RigidWalls walls({fan});
  std::mt19937 random(11);
  auto uniform = [&](double a, double b) { return a + (b - a) * double(random()) / double(std::mt19937::max()); };
  for (int n = 0; n < 3000; ++n) {
    const Vec3d x{uniform(-1.2, 1.2), uniform(-0.5, 0.5), uniform(-1.2, 1.2)};
    const double reach = uniform(0.01, 0.6);
    const WallPoint expected = closest_by_brute_force(fan, x, reach);
    WallPoint hint;
    hint.found = true;
    hint.triangle = unsigned(random() % fan.triangles.size());
    hint.rigid = 0;
    const WallPoint* const hints[] = {nullptr, &hint};
    for (const WallPoint* h : hints) {
      const WallPoint w = walls.closest(x, reach, h);
      ASSERT_EQ(w.found, expected.found) << n;
      if (!expected.found) continue;
      ASSERT_EQ(w.triangle, expected.triangle) << n;
      ASSERT_EQ(w.distance, expected.distance) << n;
      ASSERT_EQ(w.point.x, expected.point.x);
      ASSERT_EQ(w.point.y, expected.point.y);
      ASSERT_EQ(w.point.z, expected.point.z);
    }
  }
}

SurfaceMesh tetrahedron() {
  SurfaceMesh m;
  m.position = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.normal.assign(4, {});
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return m;
}

TEST(mesh_Check, CgalPassesATetrahedronWithItsVolumeAndArea) {
  const MeshCheck c = check_mesh(tetrahedron());
  EXPECT_TRUE(c.passed());
  EXPECT_NEAR(c.volume_m3, 1.0 / 6, 1e-12);
  EXPECT_NEAR(c.area_m2, 1.5 + std::sqrt(3.0) / 2, 1e-12);
}

TEST(mesh_Check, CgalFindsAFlippedFaceAHoleAndAnInsideOutMesh) {
  SurfaceMesh flipped = tetrahedron();
  std::swap(flipped.triangles[3][0], flipped.triangles[3][1]);
  EXPECT_FALSE(check_mesh(flipped).oriented);

  SurfaceMesh open = tetrahedron();
  open.triangles.pop_back();
  const MeshCheck o = check_mesh(open);
  EXPECT_FALSE(o.closed);
  EXPECT_EQ(o.border_edges, 3u);

  SurfaceMesh inside_out = tetrahedron();
  for (auto& t : inside_out.triangles) std::swap(t[0], t[1]);
  const MeshCheck i = check_mesh(inside_out);
  EXPECT_TRUE(i.closed);
  EXPECT_FALSE(i.outward);
  EXPECT_FALSE(i.passed());
}

TEST(mesh_Check, CgalFindsSelfIntersections) {
  SurfaceMesh two = tetrahedron();
  // A second tetrahedron poking through the first.
  const std::uint32_t base = 4;
  for (int v = 0; v < 4; ++v) two.position.push_back(two.position[v] + Vec3d{0.2, 0.2, 0.2});
  for (int t = 0; t < 4; ++t)
    two.triangles.push_back({two.triangles[t][0] + base, two.triangles[t][1] + base, two.triangles[t][2] + base});
  two.normal.assign(8, {});
  EXPECT_TRUE(check_mesh(two).self_intersecting);
}

}  // namespace
}  // namespace dp::mesh
