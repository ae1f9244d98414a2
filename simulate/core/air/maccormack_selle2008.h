#pragma once
// MacCormack advection (Selle, Fedkiw, Kim, Liu & Osher 2008), the optional
// second-order alternative to plain semi-Lagrangian: a forward step
// phi^ = A(phi), a backward step phi~ = A^R(phi^), and the corrected
// phi^ + (phi - phi~)/2, clamped to the values the forward step interpolated
// from so that no new extrema appear.
#include "air/semi_lagrangian_stam1999.h"

namespace dp {

template <class T>
struct MacCormackCorrect {
  Lattice<T> source;  // phi at the start of the step
  FaceVelocity velocity;
  float dt;
  const T* forward;   // phi^
  const T* backward;  // phi~
  T* out;

  DP_HD void operator()(std::size_t n) const {
    const int i = static_cast<int>(n % source.nx);
    const int j = static_cast<int>((n / source.nx) % source.ny);
    const int k = static_cast<int>(n / (static_cast<std::size_t>(source.nx) * source.ny));
    const Vec3 x = source.origin + source.dx * Vec3{static_cast<float>(i), static_cast<float>(j), static_cast<float>(k)};
    T lo, hi;
    source.sample(trace_back(velocity, x, dt), &lo, &hi);
    T v = forward[n] + static_cast<T>(0.5) * (source.value[n] - backward[n]);
    out[n] = v < lo ? lo : (v > hi ? hi : v);
  }
};

}  // namespace dp
