#pragma once
// Trilinear interpolation of the grid's fields at any point: cell-centred
// scalars and each staggered velocity component on its own face lattice.
// Points outside a lattice take its nearest boundary value (clamping), the
// usual closure of semi-Lagrangian advection (Stam 1999).
#include "air/mac_grid.h"
#include "backend/host_device.h"
#include "math/vec3.h"

namespace dp {

// A lattice of values at origin + (i + offset) dx, size nx x ny x nz.
template <class T>
struct Lattice {
  const T* value;
  Vec3 origin;  // position of value[0]
  float dx;
  int nx, ny, nz;

  DP_HD T at(int i, int j, int k) const { return value[(static_cast<std::size_t>(k) * ny + j) * nx + i]; }

  // The value at p, and the smallest and largest of the eight values it
  // was interpolated from (MacCormack's clamp, Selle et al. 2008).
  DP_HD T sample(Vec3 p, T* lo = nullptr, T* hi = nullptr) const {
    int i0, j0, k0;
    float tx, ty, tz;
    locate((p.x - origin.x) / dx, nx, i0, tx);
    locate((p.y - origin.y) / dx, ny, j0, ty);
    locate((p.z - origin.z) / dx, nz, k0, tz);
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
  DP_HD static void locate(float s, int n, int& i, float& t) {
    const float top = static_cast<float>(n - 1);
    s = s < 0.0f ? 0.0f : (s > top ? top : s);
    i = static_cast<int>(floorf(s));
    if (i > n - 2) i = n - 2 > 0 ? n - 2 : 0;
    t = s - static_cast<float>(i);
    if (n == 1) t = 0.0f;
  }
};

template <class T>
DP_HD inline Lattice<T> cell_lattice(const MacGrid& g, const T* v) {
  return Lattice<T>{v, g.origin + 0.5f * Vec3{g.dx, g.dx, g.dx}, g.dx, g.nx, g.ny, g.nz};
}

DP_HD inline Lattice<float> face_lattice(const MacGrid& g, int axis, const float* v) {
  return Lattice<float>{v, g.face_center(axis, 0, 0, 0), g.dx, g.face_n(axis, 0), g.face_n(axis, 1), g.face_n(axis, 2)};
}

// The three staggered components, sampled together.
struct FaceVelocity {
  Lattice<float> u, v, w;
  DP_HD Vec3 at(Vec3 p) const { return Vec3{u.sample(p), v.sample(p), w.sample(p)}; }
  DP_HD const Lattice<float>& component(int axis) const { return axis == 0 ? u : (axis == 1 ? v : w); }
};

DP_HD inline FaceVelocity face_velocity(const MacGrid& g, const float* u, const float* v, const float* w) {
  return FaceVelocity{face_lattice(g, 0, u), face_lattice(g, 1, v), face_lattice(g, 2, w)};
}

}  // namespace dp
