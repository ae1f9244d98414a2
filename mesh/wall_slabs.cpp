#include "wall_slabs.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace dp::mesh {

namespace {

// One orientation per plane: a slab does not care which side faces out.
Vec3d canonical_direction(Vec3d n) {
  for (int axis = 0; axis < 3; ++axis)
    if (n[axis] != 0) return n[axis] > 0 ? n : -n;
  return n;
}

// Planes equal to about 1e-9 (normal components, offset relative to the
// scene's size) share a key; a plane that straddles a rounding boundary
// only splits into two slabs, each still exact.
using PlaneKey = std::tuple<long long, long long, long long, long long>;

PlaneKey plane_key(Vec3d n, double offset, double scale) {
  constexpr double kResolution = 1e-9;
  return {std::llround(n.x / kResolution), std::llround(n.y / kResolution), std::llround(n.z / kResolution),
          std::llround(offset / (scale * kResolution))};
}

void extend(WallSlab& s, const std::array<Vec3d, 3>& corners) {
  for (const Vec3d& c : corners) {
    const double t = dot(c, s.normal);
    s.lo = std::min(s.lo, t), s.hi = std::max(s.hi, t);
    for (int a = 0; a < 3; ++a) s.box_lo[a] = std::min(s.box_lo[a], c[a]), s.box_hi[a] = std::max(s.box_hi[a], c[a]);
  }
}

}  // namespace

std::vector<WallSlab> coplanar_slabs(const std::vector<std::array<Vec3d, 3>>& corners, const std::vector<Vec3d>& normals) {
  double scale = 0;
  for (const auto& t : corners)
    for (const Vec3d& c : t) scale = std::max({scale, std::abs(c.x), std::abs(c.y), std::abs(c.z)});
  if (scale == 0) scale = 1;
  std::vector<WallSlab> slabs;
  std::map<PlaneKey, std::size_t> slab_of_plane;
  for (std::size_t t = 0; t < corners.size(); ++t) {
    // A degenerate triangle has no normal, but any direction bounds it: x will do.
    const Vec3d n = length_squared(normals[t]) > 0.5 ? canonical_direction(normals[t]) : Vec3d{1, 0, 0};
    const auto [it, is_new] = slab_of_plane.try_emplace(plane_key(n, dot(corners[t][0], n), scale), slabs.size());
    if (is_new) {
      WallSlab s;
      s.normal = n;
      s.lo = s.hi = dot(corners[t][0], n);
      s.box_lo = s.box_hi = corners[t][0];
      slabs.push_back(s);
    }
    extend(slabs[it->second], corners[t]);
  }
  return slabs;
}

}  // namespace dp::mesh
