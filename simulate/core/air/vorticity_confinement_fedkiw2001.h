#pragma once
// Vorticity confinement (Fedkiw, Stam & Jensen 2001, Sec. 3.3), which the
// paper uses to keep the coarse grid's small eddies (Sec. 4.2):
//   omega = curl u,  N = grad|omega| / |grad|omega||,  f = epsilon dx (N x omega).
// Derivatives are central differences at cell centres, one-sided next to
// walls and non-air cells. epsilon is in 1/s in SI units.
#include "air/cell_kind.h"
#include "air/mac_grid.h"

namespace dp {

// The velocity at cell centres: the mean of each component's two faces.
struct CellCentredVelocity {
  MacGrid grid;
  const float* u;
  const float* v;
  const float* w;
  Vec3* out;
  DP_HD void operator()(std::size_t c) const {
    int i, j, k;
    grid.cell_coords(c, i, j, k);
    (*this)(i, j, k);
  }
  DP_HD void operator()(int i, int j, int k) const { out[grid.cell(i, j, k)] = at(i, j, k); }
  DP_HD_INLINE Vec3 at(int i, int j, int k) const {
    return Vec3{0.5f * (u[grid.face(0, i, j, k)] + u[grid.face(0, i + 1, j, k)]),
                0.5f * (v[grid.face(1, i, j, k)] + v[grid.face(1, i, j + 1, k)]),
                0.5f * (w[grid.face(2, i, j, k)] + w[grid.face(2, i, j, k + 1)])};
  }
};

// 1/dx and 1/(2 dx), the scales of a one-sided and a central difference,
// found once per pass rather than divided out per derivative.
struct DifferenceScales {
  float one_step, two_steps;
};
DP_HD inline DifferenceScales difference_scales(float dx) { return DifferenceScales{1.0f / dx, 1.0f / (2.0f * dx)}; }

// A cell-centred field's value at cell (i, j, k).
template <class T>
struct CellValues {
  MacGrid grid;
  const T* value;
  DP_HD_INLINE T operator()(int i, int j, int k) const { return value[grid.cell(i, j, k)]; }
};

// d value / d x_axis at air cell (i, j, k), from its air neighbours:
// central between two, one-sided next to one, 0 without; value_at(i, j, k)
// gives a cell's value.
template <class ValueAt>
DP_HD_INLINE auto air_derivative(const CellKinds& cells, DifferenceScales scales, const ValueAt& value_at, int i, int j,
                                 int k, int axis) -> decltype(value_at(i, j, k)) {
  int pi, pj, pk, mi, mj, mk;
  const bool plus = cells.neighbour(i, j, k, axis, 1, pi, pj, pk) && cells.at(pi, pj, pk) == kAirCell;
  const bool minus = cells.neighbour(i, j, k, axis, 0, mi, mj, mk) && cells.at(mi, mj, mk) == kAirCell;
  const auto hi = plus ? value_at(pi, pj, pk) : value_at(i, j, k);
  const auto lo = minus ? value_at(mi, mj, mk) : value_at(i, j, k);
  if (!plus && !minus) return hi - hi;
  return (hi - lo) * (plus && minus ? scales.two_steps : scales.one_step);
}

struct ComputeVorticity {
  CellKinds cells;
  DifferenceScales scales;
  const Vec3* velocity;  // cell-centred
  Vec3* omega;
  float* omega_norm;
  DP_HD void operator()(int i, int j, int k) const {
    const std::size_t c = cells.grid.cell(i, j, k);
    if (cells.kind[c] != kAirCell) {
      omega[c] = Vec3{};
      omega_norm[c] = 0;
      return;
    }
    const CellValues<Vec3> at{cells.grid, velocity};
    const Vec3 dx = air_derivative(cells, scales, at, i, j, k, 0);
    const Vec3 dy = air_derivative(cells, scales, at, i, j, k, 1);
    const Vec3 dz = air_derivative(cells, scales, at, i, j, k, 2);
    omega[c] = Vec3{dy.z - dz.y, dz.x - dx.z, dx.y - dy.x};
    omega_norm[c] = length(omega[c]);
  }
};

struct ComputeConfinementForce {
  CellKinds cells;
  DifferenceScales scales;
  const Vec3* omega;
  const float* omega_norm;
  float epsilon;
  Vec3* force;
  DP_HD void operator()(int i, int j, int k) const {
    const std::size_t c = cells.grid.cell(i, j, k);
    force[c] = Vec3{};
    if (cells.kind[c] != kAirCell) return;
    const CellValues<float> norm_at{cells.grid, omega_norm};
    const Vec3 grad{air_derivative(cells, scales, norm_at, i, j, k, 0), air_derivative(cells, scales, norm_at, i, j, k, 1),
                    air_derivative(cells, scales, norm_at, i, j, k, 2)};
    const float g = length(grad);
    // A flat |omega| has no direction to confine towards.
    if (!(g > 1e-20f)) return;
    force[c] = (epsilon * cells.grid.dx) * cross((1.0f / g) * grad, omega[c]);
  }
};

// u_a += dt f_a on one axis' faces, f the mean of the two cells' forces.
template <int Axis>
struct AddCellForceToFaces {
  static constexpr int axis = Axis;
  MacGrid grid;
  const Vec3* force;
  float dt;
  float* u;
  DP_HD void operator()(int i, int j, int k) const {
    const std::size_t f = grid.face(axis, i, j, k);
    const int a = (axis == 0 ? i : (axis == 1 ? j : k));
    const int lo = a > 0 ? a - 1 : 0, hi = a < grid.n(axis) ? a : a - 1;
    const Vec3 fl = force[grid.cell(axis == 0 ? lo : i, axis == 1 ? lo : j, axis == 2 ? lo : k)];
    const Vec3 fh = force[grid.cell(axis == 0 ? hi : i, axis == 1 ? hi : j, axis == 2 ? hi : k)];
    u[f] += dt * 0.5f * (fl[axis] + fh[axis]);
  }
};

}  // namespace dp
