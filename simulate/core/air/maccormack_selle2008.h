#pragma once
// MacCormack advection (Selle, Fedkiw, Kim, Liu & Osher 2008), the optional
// second-order alternative to plain semi-Lagrangian: a forward step
// phi^ = A(phi), a backward step phi~ = A^R(phi^), and the corrected
// phi^ + (phi - phi~)/2, clamped to the values the forward step interpolated
// from so that no new extrema appear.
#include "air/semi_lagrangian_stam1999.h"

namespace dp {

template <class T, int Points>
struct MacCormackCorrect {
  static_assert(std::is_same_v<T, float>, "the back-trace samples float velocity lattices with T's lanes");
  Lattice<T> source;  // phi at the start of the step
  FaceVelocity velocity;
  float cells_per_speed;  // dt / dx
  const T* forward;   // phi^
  const T* backward;  // phi~
  T* out;

  DP_HD void operator()(int i, int j, int k) const {
    const std::size_t n = source.index(i, j, k);
    T lo, hi;
    source.template sample<OneLane<T>>(trace_back<Points, OneLane<T>>(velocity, i, j, k, cells_per_speed), &lo, &hi);
    const T v = forward[n] + static_cast<T>(0.5) * (source.value[n] - backward[n]);
    out[n] = v < lo ? lo : (v > hi ? hi : v);
  }
};

}  // namespace dp
