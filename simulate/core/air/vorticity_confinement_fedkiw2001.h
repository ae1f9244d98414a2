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
  DP_HD void operator()(int i, int j, int k) const {
    out[grid.cell(i, j, k)] = Vec3{0.5f * (u[grid.face(0, i, j, k)] + u[grid.face(0, i + 1, j, k)]),
                  0.5f * (v[grid.face(1, i, j, k)] + v[grid.face(1, i, j + 1, k)]),
                  0.5f * (w[grid.face(2, i, j, k)] + w[grid.face(2, i, j, k + 1)])};
  }
};

// d field / d x_axis at an air cell, from its air neighbours.
template <class T>
DP_HD_INLINE T air_derivative(const CellKinds& cells, const T* field, int i, int j, int k, int axis) {
  int pi, pj, pk, mi, mj, mk;
  const bool plus = cells.neighbour(i, j, k, axis, 1, pi, pj, pk) && cells.at(pi, pj, pk) == kAirCell;
  const bool minus = cells.neighbour(i, j, k, axis, 0, mi, mj, mk) && cells.at(mi, mj, mk) == kAirCell;
  const MacGrid& g = cells.grid;
  const T hi = plus ? field[g.cell(pi, pj, pk)] : field[g.cell(i, j, k)];
  const T lo = minus ? field[g.cell(mi, mj, mk)] : field[g.cell(i, j, k)];
  const int steps = (plus ? 1 : 0) + (minus ? 1 : 0);
  return steps == 0 ? (hi - hi) : (hi - lo) * (1.0f / (static_cast<float>(steps) * g.dx));
}

struct ComputeVorticity {
  CellKinds cells;
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
    const Vec3 dx = air_derivative(cells, velocity, i, j, k, 0);
    const Vec3 dy = air_derivative(cells, velocity, i, j, k, 1);
    const Vec3 dz = air_derivative(cells, velocity, i, j, k, 2);
    omega[c] = Vec3{dy.z - dz.y, dz.x - dx.z, dx.y - dy.x};
    omega_norm[c] = length(omega[c]);
  }
};

struct ComputeConfinementForce {
  CellKinds cells;
  const Vec3* omega;
  const float* omega_norm;
  float epsilon;
  Vec3* force;
  DP_HD void operator()(int i, int j, int k) const {
    const std::size_t c = cells.grid.cell(i, j, k);
    force[c] = Vec3{};
    if (cells.kind[c] != kAirCell) return;
    const Vec3 grad{air_derivative(cells, omega_norm, i, j, k, 0), air_derivative(cells, omega_norm, i, j, k, 1),
                    air_derivative(cells, omega_norm, i, j, k, 2)};
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
