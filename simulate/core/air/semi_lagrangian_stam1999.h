#pragma once
// Semi-Lagrangian advection (Stam 1999; paper Eq. 2-4, Alg. 1 line 9): each
// grid point takes the value found where the flow came from, traced back
// through the velocity field with the midpoint rule. Unconditionally stable;
// used for velocity and temperature. MacCormack's correction on top of it is
// in maccormack_selle2008.h.
#include <type_traits>

#include "air/staggered_sampling.h"

namespace dp {

// Where the fluid at p was a time ago; `cells_per_speed` = dt / dx, so that
// velocity times it is a displacement in cells (negative: traces forwards).
// p is point (i, j, k) of lattice `Points` (mac_shift), where the first
// velocity sample needs no corner search (LatticePointVelocity); for L,
// points i, i + 1, ... of the row.
template <int Points, class L = OneLane<float>>
DP_HD_INLINE GridPointOf<L> trace_back(const FaceVelocity& velocity, int i, int j, int k, float cells_per_speed) {
  constexpr Vec3 shift = mac_shift<Points>();
  const float half = 0.5f * cells_per_speed;
  const VelocityOf<L> at_point = LatticePointVelocity<Points>::template at<L>(velocity, i, j, k);
  const GridPointOf<L> mid{L::consecutive(i), L::ints(j), L::ints(k), shift.x - half * at_point.x,
                           shift.y - half * at_point.y, shift.z - half * at_point.z};
  const VelocityOf<L> at_mid = velocity.at<L>(mid);
  return GridPointOf<L>{mid.i, mid.j, mid.k, shift.x - cells_per_speed * at_mid.x, shift.y - cells_per_speed * at_mid.y,
                        shift.z - cells_per_speed * at_mid.z};
}

// out[n] = source(trace_back(x_n)) for every point x_n of source's lattice,
// the cell centres or the faces of one axis (`Points`, as in mac_shift).
template <class T, int Points>
struct AdvectSemiLagrangian {
  static_assert(std::is_same_v<T, float>, "the back-trace samples float velocity lattices with T's lanes");
  Lattice<T> source;
  FaceVelocity velocity;
  float cells_per_speed;  // dt / dx
  T* out;

  DP_HD void operator()(int i, int j, int k) const { advect<OneLane<T>>(i, j, k); }

#if !defined(__CUDA_ARCH__)
  // Points (i .. i + 3, j, k) at once, as SSE lanes, or (i .. i + 7, j, k)
  // as AVX lanes (CpuExec::parallel_for_3d).
  DP_HOST_INLINE void four_along_x(int i, int j, int k) const { advect<FourLanes>(i, j, k); }
  DP_HOST_INLINE void eight_along_x(int i, int j, int k) const { advect<EightLanes>(i, j, k); }
  bool lanes_fit() const {
    return FourLanes::lanes_fit(source.size()) && FourLanes::lanes_fit(velocity.u.size()) &&
           FourLanes::lanes_fit(velocity.v.size()) && FourLanes::lanes_fit(velocity.w.size());
  }
#endif

  template <class L>
  DP_HD_INLINE void advect(int i, int j, int k) const {
    L::store(out + source.index(i, j, k), source.template sample<L>(trace_back<Points, L>(velocity, i, j, k, cells_per_speed)));
  }
};

}  // namespace dp
