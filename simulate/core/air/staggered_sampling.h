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
#include "air/sample_lanes.h"
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

// GridPoint for L's points (sample_lanes.h), the offset by component.
template <class L>
struct GridPointOf {
  typename L::Int i, j, k;
  typename L::Real x, y, z;
};

template <class T>
DP_HD_INLINE GridPointOf<OneLane<T>> one_lane_of(const GridPoint& p) {
  return GridPointOf<OneLane<T>>{p.i, p.j, p.k, p.offset.x, p.offset.y, p.offset.z};
}

// Lattice index `base` + `offset` as the lower corner i and the weight t of
// i + 1, clamped to [0, n - 1]; `step` is 1, or 0 where the upper corner
// would fall off a lattice of one point.
template <class L>
struct CornerOf {
  using Int = typename L::Int;
  using Real = typename L::Real;
  Int i;
  Real t;
  int step;
  static DP_HD_INLINE CornerOf locate(Int base, Real offset, int n) {
    // floor(offset) by truncation and a select, instead of floorf, which
    // has no lanes. Offsets beyond 2^24 cells are held there first (they
    // clamp to the lattice's end all the same), so that the truncation
    // never overflows; for smaller ones the floor is floorf's (t is -0
    // rather than +0 at an offset of -0, which no trace produces), and NaN
    // lands on the lower end, as before.
    const Real far = L::reals(16777216.0f);
    const Real held = offset < -far ? -far : (offset > far ? far : offset);
    const Int truncated = L::truncate(held);
    const Int whole = L::to_real(truncated) > held ? truncated - 1 : truncated;
    const Int i = base + whole;
    const Real t = held - L::to_real(whole);
    const Int first = L::ints(0), last = L::ints(n > 1 ? n - 2 : 0);
    const Real t_first = L::reals(0.0f), t_last = L::reals(n > 1 ? 1.0f : 0.0f);
    const auto below = i < first;
    const auto above = i >= L::ints(n - 1);
    return CornerOf{below ? first : (above ? last : i), below ? t_first : (above ? t_last : t), n > 1 ? 1 : 0};
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
  template <class L = OneLane<T>>
  DP_HD_INLINE CornerOf<L> corner(int axis, const GridPointOf<L>& p) const {
    return axis == 0 ? CornerOf<L>::locate(p.i, p.x - shift.x, nx)
                     : (axis == 1 ? CornerOf<L>::locate(p.j, p.y - shift.y, ny) : CornerOf<L>::locate(p.k, p.z - shift.z, nz));
  }

  // The value at p, and the smallest and largest of the eight values it
  // was interpolated from (MacCormack's clamp, Selle et al. 2008).
  DP_HD_INLINE T sample(const GridPoint& p, T* lo = nullptr, T* hi = nullptr) const {
    return sample<OneLane<T>>(one_lane_of<T>(p), lo, hi);
  }
  template <class L>
  DP_HD_INLINE typename L::Value sample(const GridPointOf<L>& p, typename L::Value* lo = nullptr,
                                        typename L::Value* hi = nullptr) const {
    return sample<L>(corner<L>(0, p), corner<L>(1, p), corner<L>(2, p), lo, hi);
  }
  // The same from corners already located (FaceVelocity shares them between
  // components): the eight values are reached by offsets from one index.
  template <class L>
  DP_HD_INLINE typename L::Value sample(const CornerOf<L>& x, const CornerOf<L>& y, const CornerOf<L>& z,
                                        typename L::Value* lo = nullptr, typename L::Value* hi = nullptr) const {
    using V = typename L::Value;
    const std::ptrdiff_t row = nx, slab = row * ny;
    const typename L::Index c = (L::to_index(z.i) * ny + L::to_index(y.i)) * nx + L::to_index(x.i);
    const typename L::Corners corner = L::corners(value, c, x.step, y.step * row, z.step * slab);
    const V c000 = corner.v[0], c100 = corner.v[1], c010 = corner.v[2], c110 = corner.v[3];
    const V c001 = corner.v[4], c101 = corner.v[5], c011 = corner.v[6], c111 = corner.v[7];
    if (lo && hi) {
      *lo = min8(c000, c100, c010, c110, c001, c101, c011, c111);
      *hi = -min8(-c000, -c100, -c010, -c110, -c001, -c101, -c011, -c111);
    }
    const V x00 = lerp<L>(c000, c100, x.t), x10 = lerp<L>(c010, c110, x.t), x01 = lerp<L>(c001, c101, x.t),
            x11 = lerp<L>(c011, c111, x.t);
    return lerp<L>(lerp<L>(x00, x10, y.t), lerp<L>(x01, x11, y.t), z.t);
  }

  // The same at L's points whose lower corners (i, j, k), (i + 1, j, k), ...
  // and weights are known at compile time, their upper corners inside the
  // lattice: Wx, Wy, Wz are 1 for weight 1/2 and 0 for weight 0, where a
  // lerp would give its first value (a + 0 (b - a) = a for finite values)
  // and the upper layer is not read. The terms and their order are those of
  // the general sample.
  template <int Wx, int Wy, int Wz, class L = OneLane<T>>
  DP_HD_INLINE typename L::Value sample_fixed(int i, int j, int k) const {
    const std::size_t row = static_cast<std::size_t>(nx), slab = row * ny;
    const std::size_t c = index(i, j, k);
    const auto y0 = along_y<Wx, Wy, L>(c, row);
    if constexpr (Wz == 0) return y0;
    else return lerp<L>(y0, along_y<Wx, Wy, L>(c + slab, row), L::reals(0.5f));
  }

 private:
  // Points c, c + 1, ... of the lattice (L's lanes) lie next to each other
  // in memory: one load per value, no gather.
  template <int Wx, class L>
  DP_HD_INLINE typename L::Value along_x(std::size_t c) const {
    if constexpr (Wx == 0) return L::load_consecutive(value, c);
    else return lerp<L>(L::load_consecutive(value, c), L::load_consecutive(value, c + 1), L::reals(0.5f));
  }
  template <int Wx, int Wy, class L>
  DP_HD_INLINE typename L::Value along_y(std::size_t c, std::size_t row) const {
    if constexpr (Wy == 0) return along_x<Wx, L>(c);
    else return lerp<L>(along_x<Wx, L>(c), along_x<Wx, L>(c + row), L::reals(0.5f));
  }
  template <class V>
  DP_HD_INLINE static V min2(V a, V b) { return b < a ? b : a; }
  template <class V>
  DP_HD_INLINE static V min8(V a, V b, V c, V d, V e, V f, V g, V h) {
    return min2(min2(min2(a, b), min2(c, d)), min2(min2(e, f), min2(g, h)));
  }
  template <class L>
  DP_HD_INLINE static typename L::Value lerp(typename L::Value a, typename L::Value b, typename L::Real t) {
    return a + L::weight(t) * (b - a);
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

// A velocity at L's points (sample_lanes.h), by component (m/s).
template <class L>
struct VelocityOf {
  typename L::Real x, y, z;
};

// The three staggered components, sampled together (m/s).
struct FaceVelocity {
  Lattice<float> u, v, w;
  DP_HD_INLINE Vec3 at(const GridPoint& p) const {
    const VelocityOf<OneLane<float>> s = at<OneLane<float>>(one_lane_of<float>(p));
    return Vec3{s.x, s.y, s.z};
  }
  // Each axis has two shifts (0 on the faces of that axis, 0.5 for the other
  // two components) and the lattice sizes pair up likewise, so six located
  // corners serve the three components instead of nine. The shifts are the
  // MAC grid's constants (face_lattice), not read from u, v, w, so that
  // they fold where p's offset is a constant too.
  template <class L>
  DP_HD_INLINE VelocityOf<L> at(const GridPointOf<L>& p) const {
    using C = CornerOf<L>;
    const C x0 = C::locate(p.i, p.x - 0.0f, u.nx), x5 = C::locate(p.i, p.x - 0.5f, v.nx);
    const C y0 = C::locate(p.j, p.y - 0.0f, v.ny), y5 = C::locate(p.j, p.y - 0.5f, u.ny);
    const C z0 = C::locate(p.k, p.z - 0.0f, w.nz), z5 = C::locate(p.k, p.z - 0.5f, u.nz);
    return VelocityOf<L>{u.sample<L>(x0, y5, z5), v.sample<L>(x5, y0, z5), w.sample<L>(x5, y5, z0)};
  }
};

// The velocity at point (i, j, k) of lattice `Points` (for L, at points i,
// i + 1, ... of the row), as FaceVelocity::at gives it. Component C's
// corners along each axis lie half a cell below the point (weight 1/2), at
// it (weight 0), or half a cell above (weight 1/2): constants, so where
// every corner lies inside, sample_fixed serves.
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
  // Points i .. last of a row: inside() holds for all where it holds at both ends.
  template <int C>
  DP_HD static bool inside_row(const Lattice<float>& l, int i, int last, int j, int k) {
    return inside<C>(l, i, j, k) && inside<C>(l, last, j, k);
  }
  template <int C, class L>
  DP_HD_INLINE static typename L::Value component(const Lattice<float>& l, int i, int j, int k) {
    return l.template sample_fixed<weight<C, 0>(), weight<C, 1>(), weight<C, 2>(), L>(i + lower<C, 0>(), j + lower<C, 1>(),
                                                                                       k + lower<C, 2>());
  }

  template <class L = OneLane<float>>
  static DP_HD_INLINE VelocityOf<L> at(const FaceVelocity& velocity, int i, int j, int k) {
    const int last = i + L::kCount - 1;
    if (inside_row<0>(velocity.u, i, last, j, k) && inside_row<1>(velocity.v, i, last, j, k) &&
        inside_row<2>(velocity.w, i, last, j, k))
      return VelocityOf<L>{component<0, L>(velocity.u, i, j, k), component<1, L>(velocity.v, i, j, k),
                           component<2, L>(velocity.w, i, j, k)};
    constexpr Vec3 shift = mac_shift<Points>();
    return velocity.at<L>(GridPointOf<L>{L::consecutive(i), L::ints(j), L::ints(k), L::reals(shift.x), L::reals(shift.y),
                                         L::reals(shift.z)});
  }
};

DP_HD inline FaceVelocity face_velocity(const MacGrid& g, const float* u, const float* v, const float* w) {
  return FaceVelocity{face_lattice(g, 0, u), face_lattice(g, 1, v), face_lattice(g, 2, w)};
}

}  // namespace dp
