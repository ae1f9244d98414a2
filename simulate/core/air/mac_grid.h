#pragma once
// The air grid's staggered (MAC) layout (Harlow & Welch 1965, as in Stam
// 1999 / Fedkiw et al. 2001): cubic cells of size dx; temperature, vapor and
// pressure at cell centres, the velocity component along axis a on the faces
// normal to a. Cell (i, j, k) spans origin + [i, i+1] x [j, j+1] x [k, k+1] dx.
#include <cmath>
#include <cstddef>

#include "backend/host_device.h"
#include "math/vec3.h"

namespace dp {

struct MacGrid {
  Vec3 origin;
  float dx = 1;
  int nx = 1, ny = 1, nz = 1;

  DP_HD int n(int axis) const { return axis == 0 ? nx : (axis == 1 ? ny : nz); }
  DP_HD std::size_t cell_count() const { return static_cast<std::size_t>(nx) * ny * nz; }
  DP_HD std::size_t cell(int i, int j, int k) const {
    return (static_cast<std::size_t>(k) * ny + j) * nx + i;
  }
  DP_HD void cell_coords(std::size_t c, int& i, int& j, int& k) const {
    i = static_cast<int>(c % nx);
    j = static_cast<int>((c / nx) % ny);
    k = static_cast<int>(c / (static_cast<std::size_t>(nx) * ny));
  }
  DP_HD bool inside(int i, int j, int k) const { return i >= 0 && j >= 0 && k >= 0 && i < nx && j < ny && k < nz; }

  // Faces normal to `axis` form a grid one larger along that axis.
  DP_HD int face_n(int axis, int a) const { return n(a) + (a == axis ? 1 : 0); }
  DP_HD std::size_t face_count(int axis) const {
    return static_cast<std::size_t>(face_n(axis, 0)) * face_n(axis, 1) * face_n(axis, 2);
  }
  // Face (i, j, k) of `axis` lies between cells (i-1, j, k) and (i, j, k)
  // along that axis (shifted index for y and z faces likewise).
  DP_HD std::size_t face(int axis, int i, int j, int k) const {
    return (static_cast<std::size_t>(k) * face_n(axis, 1) + j) * face_n(axis, 0) + i;
  }

  DP_HD Vec3 cell_center(int i, int j, int k) const {
    return origin + dx * Vec3{i + 0.5f, j + 0.5f, k + 0.5f};
  }
  DP_HD Vec3 face_center(int axis, int i, int j, int k) const {
    return origin + dx * Vec3{i + (axis == 0 ? 0.0f : 0.5f), j + (axis == 1 ? 0.0f : 0.5f), k + (axis == 2 ? 0.0f : 0.5f)};
  }
  DP_HD Vec3 domain_max() const { return origin + dx * Vec3{static_cast<float>(nx), static_cast<float>(ny), static_cast<float>(nz)}; }
  DP_HD float cell_volume() const { return dx * dx * dx; }
};

// Cubic cells: `resolution` along the domain's longest axis; the other axes
// get whole cells, so the grid may reach slightly past domain_max.
inline MacGrid mac_grid_covering(Vec3 lo, Vec3 hi, int resolution) {
  MacGrid g;
  g.origin = lo;
  const Vec3 e = hi - lo;
  const float longest = fmaxf(e.x, fmaxf(e.y, e.z));
  g.dx = longest / static_cast<float>(resolution);
  // A hair below an integer count is rounding, not a partial cell.
  auto cells = [&](float extent) { return static_cast<int>(std::ceil(extent / g.dx - 1e-4f)) > 0 ? static_cast<int>(std::ceil(extent / g.dx - 1e-4f)) : 1; };
  g.nx = cells(e.x);
  g.ny = cells(e.y);
  g.nz = cells(e.z);
  return g;
}

}  // namespace dp
