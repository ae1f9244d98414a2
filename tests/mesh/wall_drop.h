#pragma once
// One particle on a flat rigid floor, meshed with the wall corrections, and
// the contact angle measured on the resulting mesh: the test scaffolding of
// paper Fig. 3, independent of how the mesher computes the angle.
#include <cmath>
#include <vector>

#include "contact_angle_correction.h"
#include "liquid_surface.h"
#include "rigid_walls.h"
#include "triangle_mesh.h"

namespace dp::mesh::testing {

// A square floor in the plane y = height, normal +y (counter-clockwise seen from above).
inline io::TriangleMesh floor_mesh(double height, double half_width) {
  io::TriangleMesh m;
  const float h = float(height), w = float(half_width);
  m.positions = {{-w, h, -w}, {w, h, -w}, {w, h, w}, {-w, h, w}};
  m.normals.assign(4, {0, 1, 0});
  m.triangles = {{0, 2, 1}, {0, 3, 2}};
  return m;
}

struct WallDrop {
  double radius = 0.01;        // r, also the capillary length
  double floor_height = 0.00037;  // off the lattice on purpose
  double height_over_floor = 0.8;  // particle centre above the floor, in r (the paper corrects below r)
  Vec3d centre_xz{0.0013, 0, -0.0007};
  Vec3d velocity;
  DynamicContactAngleParameters angles;
  double voxels_per_radius = 12;

  Vec3d centre() const { return {centre_xz.x, floor_height + height_over_floor * radius, centre_xz.z}; }

  // `field`, if given, receives the sampled field the mesh contours.
  SurfaceMesh mesh(bool corrected = true, ScalarGrid* field = nullptr) const {
    LiquidParticles p;
    p.position.push_back(centre());
    p.radius.push_back(radius);
    p.velocity.push_back(velocity);
    const RigidWalls walls({floor_mesh(floor_height, 1.0)});
    const ContactAngleCorrection_HochstetterKolb2017 correction(walls, {{angles}, 1.0});
    const SurfaceParameters parameters{radius, 4 * radius, radius / voxels_per_radius};
    return liquid_surface(p, parameters, corrected ? &correction : nullptr, field).mesh;
  }
};

// The angle between the liquid surface and the floor, through the liquid,
// at the contact line: triangle normals of the side surface in height bins
// just above the floor, extrapolated linearly to the floor. Only triangles
// whose horizontal direction from the drop's axis lies within
// `half_wedge_rad` of `direction` count (all of them for half_wedge >= pi).
inline double contact_angle_deg(const SurfaceMesh& mesh, const WallDrop& drop, Vec3d direction = {1, 0, 0},
                                double half_wedge_rad = M_PI) {
  const double voxel = drop.radius / drop.voxels_per_radius;
  const double lo = 1.5 * voxel, hi = 0.35 * drop.radius;
  const Vec3d axis = drop.centre();
  // Least squares of angle against height, each triangle weighted by area.
  double sw = 0, sy = 0, sa = 0, syy = 0, sya = 0;
  for (const auto& t : mesh.triangles) {
    const Vec3d a = mesh.position[t[0]], b = mesh.position[t[1]], c = mesh.position[t[2]];
    const Vec3d centroid = (1.0 / 3) * (a + b + c);
    const double y_min = std::min({a.y, b.y, c.y}) - drop.floor_height, y_max = std::max({a.y, b.y, c.y}) - drop.floor_height;
    if (y_min < lo || y_max > hi) continue;
    Vec3d radial{centroid.x - axis.x, 0, centroid.z - axis.z};
    if (half_wedge_rad < M_PI && std::acos(std::clamp(dot(normalized(radial), direction), -1.0, 1.0)) > half_wedge_rad)
      continue;
    const Vec3d n2 = cross(b - a, c - a);
    const double area = 0.5 * length(n2);
    if (!(area > 0)) continue;
    const double angle = std::acos(std::clamp(normalized(n2).y, -1.0, 1.0)) * 180 / M_PI;
    const double y = centroid.y - drop.floor_height;
    sw += area;
    sy += area * y;
    sa += area * angle;
    syy += area * y * y;
    sya += area * y * angle;
  }
  if (!(sw > 0)) return NAN;
  const double slope = (sw * sya - sy * sa) / (sw * syy - sy * sy);
  return (sa - slope * sy) / sw;  // the fit at height 0
}

}  // namespace dp::mesh::testing
