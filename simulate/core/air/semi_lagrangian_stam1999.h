#pragma once
// Semi-Lagrangian advection (Stam 1999; paper Eq. 2-4, Alg. 1 line 9): each
// grid point takes the value found where the flow came from, traced back
// through the velocity field with the midpoint rule. Unconditionally stable;
// used for velocity and temperature. MacCormack's correction on top of it is
// in maccormack_selle2008.h.
#include "air/staggered_sampling.h"

namespace dp {

// Where the fluid at p was dt ago (midpoint rule; dt < 0 traces forwards).
DP_HD inline Vec3 trace_back(const FaceVelocity& velocity, Vec3 p, float dt) {
  const Vec3 mid = p - (0.5f * dt) * velocity.at(p);
  return p - dt * velocity.at(mid);
}

// out[i] = source(trace_back(x_i)) for every point x_i of source's lattice
// (cell centres or the faces of one axis).
template <class T>
struct AdvectSemiLagrangian {
  Lattice<T> source;
  FaceVelocity velocity;
  float dt;
  T* out;

  DP_HD void operator()(std::size_t n) const {
    const int i = static_cast<int>(n % source.nx);
    const int j = static_cast<int>((n / source.nx) % source.ny);
    const int k = static_cast<int>(n / (static_cast<std::size_t>(source.nx) * source.ny));
    const Vec3 x = source.origin + source.dx * Vec3{static_cast<float>(i), static_cast<float>(j), static_cast<float>(k)};
    out[n] = source.sample(trace_back(velocity, x, dt));
  }
};

}  // namespace dp
