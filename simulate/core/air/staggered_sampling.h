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

// Lattice index `base` + `offset` as the lower corner i and the weight t of
// i + 1, clamped to [0, n - 1]; `step` is 1, or 0 where the upper corner
// would fall off a lattice of one point.
struct Corner {
  int i;
  float t;
  int step;
  static DP_HD_INLINE Corner locate(int base, float offset, int n) {
    const float whole = floorf(offset);
    Corner c{base + static_cast<int>(whole), offset - whole, 1};
    if (c.i < 0) {
      c.i = 0;
      c.t = 0.0f;
    } else if (c.i >= n - 1) {
      c.i = n > 1 ? n - 2 : 0;
      c.t = n > 1 ? 1.0f : 0.0f;
    }
    if (n < 2) c.step = 0;
    return c;
  }
};

// Values at grid points (i, j, k) + `shift` (cells: 0.5 on a cell-centred
// axis, 0 on a face axis), nx x ny x nz of them.
template <class T>
struct Lattice {
  const T* value;
  Vec3 shift;
  int nx, ny, nz;

  DP_HD std::size_t size() const { return static_cast<std::size_t>(nx) * ny * nz; }
  DP_HD std::size_t index(int i, int j, int k) const { return (static_cast<std::size_t>(k) * ny + j) * nx + i; }
  DP_HD T at(int i, int j, int k) const { return value[index(i, j, k)]; }
  // Where p falls along one axis of this lattice: the lower corner and the
  // weight of the upper one, clamped to the lattice.
  DP_HD Corner corner(int axis, const GridPoint& p) const {
    return axis == 0 ? Corner::locate(p.i, p.offset.x - shift.x, nx)
                     : (axis == 1 ? Corner::locate(p.j, p.offset.y - shift.y, ny) : Corner::locate(p.k, p.offset.z - shift.z, nz));
  }

  // The value at p, and the smallest and largest of the eight values it
  // was interpolated from (MacCormack's clamp, Selle et al. 2008).
  DP_HD_INLINE T sample(const GridPoint& p, T* lo = nullptr, T* hi = nullptr) const {
    return sample(corner(0, p), corner(1, p), corner(2, p), lo, hi);
  }
  // The same from corners already located (FaceVelocity shares them between
  // components): the eight values are reached by offsets from one index.
  DP_HD_INLINE T sample(Corner x, Corner y, Corner z, T* lo = nullptr, T* hi = nullptr) const {
    const std::size_t row = static_cast<std::size_t>(nx), slab = row * ny;
    const std::size_t c = index(x.i, y.i, z.i);
    const std::size_t di = x.step, dj = y.step * row, dk = z.step * slab;
    const T c000 = value[c], c100 = value[c + di], c010 = value[c + dj], c110 = value[c + dj + di];
    const T c001 = value[c + dk], c101 = value[c + dk + di], c011 = value[c + dk + dj], c111 = value[c + dk + dj + di];
    if (lo && hi) {
      *lo = min8(c000, c100, c010, c110, c001, c101, c011, c111);
      *hi = -min8(-c000, -c100, -c010, -c110, -c001, -c101, -c011, -c111);
    }
    const T x00 = lerp(c000, c100, x.t), x10 = lerp(c010, c110, x.t), x01 = lerp(c001, c101, x.t), x11 = lerp(c011, c111, x.t);
    return lerp(lerp(x00, x10, y.t), lerp(x01, x11, y.t), z.t);
  }

  // The same at a point whose lower corner (i, j, k) and weights are known
  // at compile time, its upper corners inside the lattice: Wx, Wy, Wz are 1
  // for weight 1/2 and 0 for weight 0, where a lerp would give its first
  // value (a + 0 (b - a) = a for finite values) and the upper layer is not
  // read. The terms and their order are those of the general sample.
  template <int Wx, int Wy, int Wz>
  DP_HD T sample_fixed(int i, int j, int k) const {
    const std::size_t row = static_cast<std::size_t>(nx), slab = row * ny;
    const std::size_t c = index(i, j, k);
    const T y0 = along_y<Wx, Wy>(c, row);
    if constexpr (Wz == 0) return y0;
    else return lerp(y0, along_y<Wx, Wy>(c + slab, row), 0.5f);
  }

 private:
  template <int Wx>
  DP_HD T along_x(std::size_t c) const {
    if constexpr (Wx == 0) return value[c];
    else return lerp(value[c], value[c + 1], 0.5f);
  }
  template <int Wx, int Wy>
  DP_HD T along_y(std::size_t c, std::size_t row) const {
    if constexpr (Wy == 0) return along_x<Wx>(c);
    else return lerp(along_x<Wx>(c), along_x<Wx>(c + row), 0.5f);
  }
  DP_HD static T min2(T a, T b) { return b < a ? b : a; }
  DP_HD static T min8(T a, T b, T c, T d, T e, T f, T g, T h) {
    return min2(min2(min2(a, b), min2(c, d)), min2(min2(e, f), min2(g, h)));
  }
  DP_HD static T lerp(T a, T b, float t) { return a + static_cast<T>(t) * (b - a); }
};

template <class T>
DP_HD inline Lattice<T> cell_lattice(const MacGrid& g, const T* v) {
  return Lattice<T>{v, Vec3{0.5f, 0.5f, 0.5f}, g.nx, g.ny, g.nz};
}

DP_HD inline Lattice<float> face_lattice(const MacGrid& g, int axis, const float* v) {
  return Lattice<float>{v, Vec3{axis == 0 ? 0.0f : 0.5f, axis == 1 ? 0.0f : 0.5f, axis == 2 ? 0.0f : 0.5f},
                        g.face_n(axis, 0), g.face_n(axis, 1), g.face_n(axis, 2)};
}

// Where the points of one of a MAC grid's lattices sit in their cell, in
// cells: the faces of axis `Points` (0, 1, 2) lie at 0 along that axis and
// 1/2 along the other two; kCellCentres at 1/2 along all three. As a
// compile-time constant it lets a kernel that visits a lattice's own points
// fold the corner search of every sample taken there.
inline constexpr int kCellCentres = 3;
template <int Points>
DP_HD constexpr Vec3 mac_shift() {
  return Vec3{Points == 0 ? 0.0f : 0.5f, Points == 1 ? 0.0f : 0.5f, Points == 2 ? 0.0f : 0.5f};
}

// The three staggered components, sampled together (m/s).
struct FaceVelocity {
  Lattice<float> u, v, w;
  // Each axis has two shifts (0 on the faces of that axis, 0.5 for the other
  // two components) and the lattice sizes pair up likewise, so six located
  // corners serve the three components instead of nine. The shifts are the
  // MAC grid's constants (face_lattice), not read from u, v, w, so that
  // they fold where p's offset is a constant too.
  DP_HD_INLINE Vec3 at(const GridPoint& p) const {
    const Corner x0 = Corner::locate(p.i, p.offset.x - 0.0f, u.nx), x5 = Corner::locate(p.i, p.offset.x - 0.5f, v.nx);
    const Corner y0 = Corner::locate(p.j, p.offset.y - 0.0f, v.ny), y5 = Corner::locate(p.j, p.offset.y - 0.5f, u.ny);
    const Corner z0 = Corner::locate(p.k, p.offset.z - 0.0f, w.nz), z5 = Corner::locate(p.k, p.offset.z - 0.5f, u.nz);
    return Vec3{u.sample(x0, y5, z5), v.sample(x5, y0, z5), w.sample(x5, y5, z0)};
  }
};

// The velocity at point (i, j, k) of lattice `Points`, as FaceVelocity::at
// gives it. Component C's corners along each axis lie half a cell below the
// point (weight 1/2), at it (weight 0), or half a cell above (weight 1/2):
// constants, so where every corner lies inside, sample_fixed serves.
template <int Points>
struct LatticePointVelocity {
  // Half cells from component C's lattice to the points along an axis: -1, 0 or 1.
  template <int C, int Axis>
  DP_HD static constexpr int half_cells() {
    return (Points == Axis ? 0 : 1) - (C == Axis ? 0 : 1);
  }
  template <int C, int Axis>
  DP_HD static constexpr int weight() { return half_cells<C, Axis>() != 0 ? 1 : 0; }
  template <int C, int Axis>
  DP_HD static constexpr int lower() { return half_cells<C, Axis>() < 0 ? -1 : 0; }

  template <int C>
  DP_HD static bool inside(const Lattice<float>& l, int i, int j, int k) {
    const int a = i + lower<C, 0>(), b = j + lower<C, 1>(), c = k + lower<C, 2>();
    return a >= 0 && b >= 0 && c >= 0 && a + 1 < l.nx && b + 1 < l.ny && c + 1 < l.nz;
  }
  template <int C>
  DP_HD static float component(const Lattice<float>& l, int i, int j, int k) {
    return l.template sample_fixed<weight<C, 0>(), weight<C, 1>(), weight<C, 2>()>(i + lower<C, 0>(), j + lower<C, 1>(),
                                                                                    k + lower<C, 2>());
  }

  static DP_HD_INLINE Vec3 at(const FaceVelocity& velocity, int i, int j, int k) {
    if (inside<0>(velocity.u, i, j, k) && inside<1>(velocity.v, i, j, k) && inside<2>(velocity.w, i, j, k))
      return Vec3{component<0>(velocity.u, i, j, k), component<1>(velocity.v, i, j, k), component<2>(velocity.w, i, j, k)};
    return velocity.at(GridPoint{i, j, k, mac_shift<Points>()});
  }
};

DP_HD inline FaceVelocity face_velocity(const MacGrid& g, const float* u, const float* v, const float* w) {
  return FaceVelocity{face_lattice(g, 0, u), face_lattice(g, 1, v), face_lattice(g, 2, w)};
}

}  // namespace dp
