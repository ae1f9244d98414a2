#pragma once
// Buoyancy, paper Eq. 5 (Fedkiw, Stam & Jensen 2001):
//   f = -alpha rho z + beta (T - T_amb) z,  z the unit vector pointing up.
// The paper writes g^ ("normalized direction of gravity") for z, which would
// make warm air sink; the text's intent ("make warm air rise and dense air
// sink") and Fedkiw's original both mean up = -g^ (docs/paper-map.md,
// departures). rho is the vapor density: alpha > 0 lets vapor-laden air sink
// as Fedkiw's smoke does; the default alpha < 0 lets humid air rise, as it
// does in nature (water vapor is lighter than dry air).
#include "air/cell_kind.h"
#include "air/mac_grid.h"

namespace dp {

struct BuoyancyParameters {
  Vec3 up;  // unit, against gravity
  float alpha, beta;
  DP_HD float magnitude(double vapor, float temperature_excess) const {
    return -alpha * static_cast<float>(vapor) + beta * temperature_excess;
  }
};

// u_a += dt f_a on the faces of one axis, f from the mean of the two cells
// the face separates (faces on the domain boundary use their one cell; the
// boundary conditions overwrite them where they are walls).
template <int Axis>
struct AddBuoyancy {
  static constexpr int axis = Axis;
  MacGrid grid;
  BuoyancyParameters p;
  const double* vapor;
  const float* temperature_excess;  // T - T_amb
  float dt;
  float* u;

  DP_HD void operator()(int i, int j, int k) const {
    const float up = p.up[axis];
    if (up == 0.0f) return;
    const std::size_t f = grid.face(axis, i, j, k);
    const int a = (axis == 0 ? i : (axis == 1 ? j : k));
    const int lo = a > 0 ? a - 1 : 0, hi = a < grid.n(axis) ? a : a - 1;
    const std::size_t cl = grid.cell(axis == 0 ? lo : i, axis == 1 ? lo : j, axis == 2 ? lo : k);
    const std::size_t ch = grid.cell(axis == 0 ? hi : i, axis == 1 ? hi : j, axis == 2 ? hi : k);
    const float f_mean = 0.5f * (p.magnitude(vapor[cl], temperature_excess[cl]) + p.magnitude(vapor[ch], temperature_excess[ch]));
    u[f] += dt * up * f_mean;
  }
};

}  // namespace dp
