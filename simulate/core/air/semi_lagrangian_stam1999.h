#pragma once
// Semi-Lagrangian advection (Stam 1999; paper Eq. 2-4, Alg. 1 line 9): each
// grid point takes the value found where the flow came from, traced back
// through the velocity field with the midpoint rule. Unconditionally stable;
// used for velocity and temperature. MacCormack's correction on top of it is
// in maccormack_selle2008.h.
#include "air/staggered_sampling.h"

namespace dp {

// Where the fluid at p was a time ago; `cells_per_speed` = dt / dx, so that
// velocity times it is a displacement in cells (negative: traces forwards).
// p is point (i, j, k) of lattice `Points` (mac_shift), where the first
// velocity sample needs no corner search (LatticePointVelocity).
template <int Points>
DP_HD_INLINE GridPoint trace_back(const FaceVelocity& velocity, int i, int j, int k, float cells_per_speed) {
  GridPoint p{i, j, k, mac_shift<Points>()};
  GridPoint mid = p;
  mid.offset -= (0.5f * cells_per_speed) * LatticePointVelocity<Points>::at(velocity, i, j, k);
  p.offset -= cells_per_speed * velocity.at(mid);
  return p;
}

// out[n] = source(trace_back(x_n)) for every point x_n of source's lattice,
// the cell centres or the faces of one axis (`Points`, as in mac_shift).
template <class T, int Points>
struct AdvectSemiLagrangian {
  Lattice<T> source;
  FaceVelocity velocity;
  float cells_per_speed;  // dt / dx
  T* out;

  DP_HD void operator()(int i, int j, int k) const {
    out[source.index(i, j, k)] = source.sample(trace_back<Points>(velocity, i, j, k, cells_per_speed));
  }
};

}  // namespace dp
