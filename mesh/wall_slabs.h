#pragma once
// A lower bound of the distance from a point to many rigid triangles at the
// cost of a dot product: triangles that share a plane (a floor fanned into
// slivers, a wall column cut into rings) are held by the slab between the
// lowest and highest of their corners along the plane's normal, and a point
// is at least as far from each of them as from the slab. It lets a search
// that cannot find anything be skipped without looking.
#include <array>
#include <vector>

#include "vec3d.h"

namespace dp::mesh {

struct WallSlab {
  Vec3d normal;         // unit
  double lo = 0, hi = 0;  // the corners' range of dot(corner, normal)
  Vec3d box_lo, box_hi;   // the corners' bounding box
};

// Triangles (corners, unit normals) grouped into slabs of (nearly) one plane;
// a triangle without a normal gets a slab of its own.
std::vector<WallSlab> coplanar_slabs(const std::vector<std::array<Vec3d, 3>>& corners, const std::vector<Vec3d>& normals);

inline double distance_to_slab(const WallSlab& s, Vec3d p) {
  const double t = dot(p, s.normal);
  return std::max(std::max(s.lo - t, t - s.hi), 0.0);
}

// How far every point of the box [centre - half, centre + half] is from the slab at least.
inline double distance_to_slab(const WallSlab& s, Vec3d centre, Vec3d half) {
  const double t = dot(centre, s.normal);
  const double spread = std::abs(s.normal.x) * half.x + std::abs(s.normal.y) * half.y + std::abs(s.normal.z) * half.z;
  return std::max(std::max(s.lo - (t + spread), (t - spread) - s.hi), 0.0);
}

}  // namespace dp::mesh
