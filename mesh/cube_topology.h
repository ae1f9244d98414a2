#pragma once
// Numbering of a grid cube's corners, edges and faces.
//   corner c: offset (c & 1, c >> 1 & 1, c >> 2 & 1) from the cube's lowest node;
//   edge e:   along axis e / 4, from its lower corner whose coordinates on the
//             two other axes, (axis + 1) % 3 and (axis + 2) % 3, are the bits
//             of e % 4;
//   face f:   normal to axis f / 2, on the low (f even) or high (f odd) side.
#include <array>

namespace dp::mesh {

inline constexpr int kCubeCorners = 8, kCubeEdges = 12, kCubeFaces = 6;

constexpr int corner_coordinate(int corner, int axis) { return (corner >> axis) & 1; }

constexpr int corner_at(int x, int y, int z) { return x | (y << 1) | (z << 2); }

constexpr int edge_axis(int edge) { return edge / 4; }

// The edge's corner with the smaller coordinate along its axis.
constexpr int edge_lower_corner(int edge) {
  const int axis = edge_axis(edge), bits = edge % 4;
  return ((bits & 1) << ((axis + 1) % 3)) | ((bits >> 1) << ((axis + 2) % 3));
}

constexpr int edge_upper_corner(int edge) { return edge_lower_corner(edge) | (1 << edge_axis(edge)); }

// The edge joining two corners that differ in exactly one coordinate.
constexpr int edge_between(int a, int b) {
  const int differ = a ^ b;
  const int axis = differ == 1 ? 0 : differ == 2 ? 1 : 2;
  const int lower = a & b;
  const int bits = corner_coordinate(lower, (axis + 1) % 3) | (corner_coordinate(lower, (axis + 2) % 3) << 1);
  return axis * 4 + bits;
}

// The face's four corners in counter-clockwise order seen from outside the
// cube (right-handed about the outward normal).
constexpr std::array<int, 4> face_corners_counterclockwise(int face) {
  const int axis = face / 2, side = face % 2;
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  // (u, v) = (0,0), (1,0), (1,1), (0,1) turns counter-clockwise about +axis
  // because u x v = +axis; the low face's outward normal is -axis.
  constexpr int uv_high[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  constexpr int uv_low[4][2] = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
  std::array<int, 4> corners{};
  for (int n = 0; n < 4; ++n) {
    const int* uv = side ? uv_high[n] : uv_low[n];
    corners[n] = (side << axis) | (uv[0] << u) | (uv[1] << v);
  }
  return corners;
}

}  // namespace dp::mesh
