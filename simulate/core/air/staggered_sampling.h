#pragma once
// Trilinear interpolation of the grid's fields: cell-centred scalars and each
// staggered velocity component on its own face lattice. Points outside a
// lattice take its nearest boundary value (clamping), the usual closure of
// semi-Lagrangian advection (Stam 1999).
//
// Points are kept in grid units as an integer cell index plus a small
// offset (`GridPoint`), not as world coordinates: a back-traced grid point
// then differs from its origin only in the offset, which float holds to
// 1e-7 of the displacement instead of 1e-7 of the distance from the world
// origin. World coordinates rounded the mirror image of a point differently
// from the point, and that alone broke a symmetric flow's symmetry by 1e-5
// within 60 steps.
#include "air/mac_grid.h"
#include "backend/host_device.h"
#include "math/vec3.h"

namespace dp {

// origin + dx ((i, j, k) + offset)
struct GridPoint {
  int i, j, k;
  Vec3 offset;
};

DP_HD inline GridPoint grid_point_of(const MacGrid& g, Vec3 p) {
  const Vec3 x = (1.0f / g.dx) * (p - g.origin);
  const float fi = floorf(x.x), fj = floorf(x.y), fk = floorf(x.z);
  return GridPoint{static_cast<int>(fi), static_cast<int>(fj), static_cast<int>(fk), Vec3{x.x - fi, x.y - fj, x.z - fk}};
}

// Values at grid points (i, j, k) + `shift` (cells: 0.5 on a cell-centred
// axis, 0 on a face axis), nx x ny x nz of them.
template <class T>
struct Lattice {
  const T* value;
  Vec3 shift;
  int nx, ny, nz;

  DP_HD std::size_t size() const { return static_cast<std::size_t>(nx) * ny * nz; }
  DP_HD T at(int i, int j, int k) const { return value[(static_cast<std::size_t>(k) * ny + j) * nx + i]; }
  // The grid point of value[n].
  DP_HD GridPoint point(std::size_t n) const {
    return GridPoint{static_cast<int>(n % nx), static_cast<int>((n / nx) % ny),
                     static_cast<int>(n / (static_cast<std::size_t>(nx) * ny)), shift};
  }

  // The value at p, and the smallest and largest of the eight values it
  // was interpolated from (MacCormack's clamp, Selle et al. 2008).
  DP_HD T sample(const GridPoint& p, T* lo = nullptr, T* hi = nullptr) const {
    int i0, j0, k0;
    float tx, ty, tz;
    locate(p.i, p.offset.x - shift.x, nx, i0, tx);
    locate(p.j, p.offset.y - shift.y, ny, j0, ty);
    locate(p.k, p.offset.z - shift.z, nz, k0, tz);
    const int i1 = i0 + 1 < nx ? i0 + 1 : i0, j1 = j0 + 1 < ny ? j0 + 1 : j0, k1 = k0 + 1 < nz ? k0 + 1 : k0;
    const T c000 = at(i0, j0, k0), c100 = at(i1, j0, k0), c010 = at(i0, j1, k0), c110 = at(i1, j1, k0);
    const T c001 = at(i0, j0, k1), c101 = at(i1, j0, k1), c011 = at(i0, j1, k1), c111 = at(i1, j1, k1);
    if (lo && hi) {
      *lo = min8(c000, c100, c010, c110, c001, c101, c011, c111);
      *hi = -min8(-c000, -c100, -c010, -c110, -c001, -c101, -c011, -c111);
    }
    const T x00 = lerp(c000, c100, tx), x10 = lerp(c010, c110, tx), x01 = lerp(c001, c101, tx), x11 = lerp(c011, c111, tx);
    return lerp(lerp(x00, x10, ty), lerp(x01, x11, ty), tz);
  }

 private:
  DP_HD static T min2(T a, T b) { return b < a ? b : a; }
  DP_HD static T min8(T a, T b, T c, T d, T e, T f, T g, T h) {
    return min2(min2(min2(a, b), min2(c, d)), min2(min2(e, f), min2(g, h)));
  }
  DP_HD static T lerp(T a, T b, float t) { return a + static_cast<T>(t) * (b - a); }
  // Lattice index `base` + `offset` as the lower corner i and weight t,
  // clamped to [0, n - 1].
  DP_HD static void locate(int base, float offset, int n, int& i, float& t) {
    const float whole = floorf(offset);
    i = base + static_cast<int>(whole);
    t = offset - whole;
    if (i < 0) {
      i = 0;
      t = 0.0f;
    } else if (i >= n - 1) {
      i = n > 1 ? n - 2 : 0;
      t = n > 1 ? 1.0f : 0.0f;
    }
  }
};

template <class T>
DP_HD inline Lattice<T> cell_lattice(const MacGrid& g, const T* v) {
  return Lattice<T>{v, Vec3{0.5f, 0.5f, 0.5f}, g.nx, g.ny, g.nz};
}

DP_HD inline Lattice<float> face_lattice(const MacGrid& g, int axis, const float* v) {
  return Lattice<float>{v, Vec3{axis == 0 ? 0.0f : 0.5f, axis == 1 ? 0.0f : 0.5f, axis == 2 ? 0.0f : 0.5f},
                        g.face_n(axis, 0), g.face_n(axis, 1), g.face_n(axis, 2)};
}

// The three staggered components, sampled together (m/s).
struct FaceVelocity {
  Lattice<float> u, v, w;
  DP_HD Vec3 at(const GridPoint& p) const { return Vec3{u.sample(p), v.sample(p), w.sample(p)}; }
  DP_HD const Lattice<float>& component(int axis) const { return axis == 0 ? u : (axis == 1 ? v : w); }
};

DP_HD inline FaceVelocity face_velocity(const MacGrid& g, const float* u, const float* v, const float* w) {
  return FaceVelocity{face_lattice(g, 0, u), face_lattice(g, 1, v), face_lattice(g, 2, w)};
}

}  // namespace dp
