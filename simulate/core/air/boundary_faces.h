#pragma once
// The grid's boundary faces, side by side: x-, x+, y-, y+, z-, z+, each a
// 2-D array over the other two axes, first one fastest. An index b in
// [0, boundary_face_count) names one: its axis, side, face index and the
// cell inside it. Sums over the open faces (the vapor ledger's transport and
// diffusion terms) run over these indices.
#include <cstddef>

#include "air/mac_grid.h"
#include "backend/host_device.h"

namespace dp {

struct BoundaryFace {
  int axis;
  bool high;
  std::size_t face, cell;
};

DP_HD inline std::size_t boundary_side_count(const MacGrid& g, int axis) {
  return axis == 0 ? static_cast<std::size_t>(g.ny) * g.nz
                   : (axis == 1 ? static_cast<std::size_t>(g.nx) * g.nz : static_cast<std::size_t>(g.nx) * g.ny);
}
DP_HD inline std::size_t boundary_face_count(const MacGrid& g) {
  return 2 * (boundary_side_count(g, 0) + boundary_side_count(g, 1) + boundary_side_count(g, 2));
}

DP_HD inline BoundaryFace boundary_face(const MacGrid& g, std::size_t b) {
  int axis = 0;
  while (b >= 2 * boundary_side_count(g, axis)) b -= 2 * boundary_side_count(g, axis++);
  const std::size_t per_side = boundary_side_count(g, axis);
  const bool high = b >= per_side;
  const std::size_t m = high ? b - per_side : b;
  const int n0 = axis == 0 ? g.ny : g.nx;
  const int p = static_cast<int>(m % n0), q = static_cast<int>(m / n0);
  const int at = high ? g.n(axis) : 0;      // the face
  const int inner = high ? g.n(axis) - 1 : 0;  // the cell inside it
  if (axis == 0) return {0, high, g.face(0, at, p, q), g.cell(inner, p, q)};
  if (axis == 1) return {1, high, g.face(1, p, at, q), g.cell(p, inner, q)};
  return {2, high, g.face(2, p, q, at), g.cell(p, q, inner)};
}

}  // namespace dp
