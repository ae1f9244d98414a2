#pragma once
// How many grid points the sampling code (staggered_sampling.h) works on at
// once. It is written once over a lanes policy: OneLane, for every caller
// and for all GPU work, or FourLanes, four consecutive points of an x row
// as SSE vectors, which the CPU launcher uses for the semi-Lagrangian pass
// (MacCormack's correction pass stays one point at a time) and for the
// multigrid transfers (multigrid_mcadams2010.h). A back-trace
// is some 400 scalar instructions around data-dependent gathers, which g++
// does not vectorise by itself on baseline x86-64, and it was 40 % of the
// CPU air step (docs/benchmarks.md). Both policies run the same
// floating-point operations in the same order on each point, so for
// finite velocity fields the results are the same bit for bit (tested).
// (With a non-finite velocity a group of four may take the general
// sampling path where one point would take the fixed-weight one, and
// 0 * inf differs from not multiplying; the step stops on such a field.)
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "backend/host_device.h"

namespace dp {

// One point. T is the type of the sampled values (float or double);
// coordinates and weights are float.
template <class T>
struct OneLane {
  using Value = T;
  using Real = float;
  using Int = int;
  using Index = std::ptrdiff_t;  // a point's position in a lattice
  static constexpr int kCount = 1;

  DP_HD_INLINE static Real reals(float v) { return v; }
  DP_HD_INLINE static Int ints(int v) { return v; }
  DP_HD_INLINE static Int truncate(Real v) { return static_cast<int>(v); }
  DP_HD_INLINE static Real to_real(Int v) { return static_cast<float>(v); }
  DP_HD_INLINE static Index to_index(Int v) { return v; }
  // Points first, first + 1, ... (one here).
  DP_HD_INLINE static Int consecutive(int first) { return first; }
  DP_HD_INLINE static Value weight(Real t) { return static_cast<T>(t); }
  DP_HD_INLINE static Value load(const T* p, Index i) { return p[i]; }
  // p[first], p[first + 1], ... (one here).
  DP_HD_INLINE static Value load_consecutive(const T* p, std::size_t first) { return p[first]; }
  // Lattice corners: each point's p[c + d] for d = 0, di, dj, dj + di, dk,
  // dk + di, dk + dj, dk + dj + di, in that order.
  struct Corners {
    Value v[8];
  };
  DP_HD_INLINE static Corners corners(const T* p, Index c, std::ptrdiff_t di, std::ptrdiff_t dj, std::ptrdiff_t dk) {
    const T* at = p + c;
    return Corners{{at[0], at[di], at[dj], at[dj + di], at[dk], at[dk + di], at[dk + dj], at[dk + dj + di]}};
  }
  DP_HD_INLINE static void store(T* p, Value v) { *p = v; }
};

#if !defined(__CUDA_ARCH__)
// Four points, as GCC/Clang vector extensions, in host code only (nvcc's
// host pass takes them too, so the CPU backend's functors are the same in
// .cu and .cpp files). Lattice positions are 32-bit lanes: the CPU
// launcher takes this path only for lattices of fewer than 2^31 points
// (lanes_fit).
struct FourLanes {
  typedef float Real __attribute__((vector_size(16)));
  typedef int Int __attribute__((vector_size(16)));
  using Value = Real;
  using Index = Int;
  static constexpr int kCount = 4;

  static Real reals(float v) { return Real{v, v, v, v}; }
  static Int ints(int v) { return Int{v, v, v, v}; }
  static Int truncate(Real v) { return __builtin_convertvector(v, Int); }
  static Real to_real(Int v) { return __builtin_convertvector(v, Real); }
  static Index to_index(Int v) { return v; }
  static Int consecutive(int first) { return Int{first, first + 1, first + 2, first + 3}; }
  static Value weight(Real t) { return t; }
  static Value load(const float* p, Index i) { return Value{p[i[0]], p[i[1]], p[i[2]], p[i[3]]}; }
  static Value load_consecutive(const float* p, std::size_t first) { return load_row(p + first); }
  // OneLane::corners for four points: each lane's position is taken out of
  // the vector once, and its eight corners are loaded at fixed offsets from
  // it, rather than every corner's position being formed in a vector and
  // taken apart lane by lane (a third of the back-trace's instructions).
  struct Corners {
    Value v[8];
  };
  DP_HOST_INLINE static Corners corners(const float* p, Index c, std::ptrdiff_t di, std::ptrdiff_t dj, std::ptrdiff_t dk) {
    const float* const at[kCount] = {p + c[0], p + c[1], p + c[2], p + c[3]};
    Corners k;
    if (di == 1) {  // neighbours along x: one 8-byte load per lane for both
      gather_pair(at, 0, k.v[0], k.v[1]);
      gather_pair(at, dj, k.v[2], k.v[3]);
      gather_pair(at, dk, k.v[4], k.v[5]);
      gather_pair(at, dk + dj, k.v[6], k.v[7]);
      return k;
    }
    const std::ptrdiff_t d[8] = {0, di, dj, dj + di, dk, dk + di, dk + dj, dk + dj + di};
    for (int n = 0; n < 8; ++n) k.v[n] = gather(at, d[n]);
    return k;
  }
  DP_HOST_INLINE static Value gather(const float* const* at, std::ptrdiff_t d) { return Value{at[0][d], at[1][d], at[2][d], at[3][d]}; }
  // Each lane's at[d] into `first` and at[d + 1] into `second`.
  DP_HOST_INLINE static void gather_pair(const float* const* at, std::ptrdiff_t d, Value& first, Value& second) {
    typedef double Pairs __attribute__((vector_size(16)));
    double q[kCount];
    for (int l = 0; l < kCount; ++l) std::memcpy(&q[l], at[l] + d, sizeof(double));
    const Value lanes01 = reinterpret_cast<Value>(Pairs{q[0], q[1]}), lanes23 = reinterpret_cast<Value>(Pairs{q[2], q[3]});
    first = pick<0, 2, 4, 6>(lanes01, lanes23);
    second = pick<1, 3, 5, 7>(lanes01, lanes23);
  }
  static void store(float* p, Value v) {
    for (int l = 0; l < kCount; ++l) p[l] = v[l];
  }
  // p[0 .. 3], one unaligned load.
  static Value load_row(const float* p) {
    Value v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  // Lanes A, B, C, D of the eight of a then b.
  template <int A, int B, int C, int D>
  static Value pick(Value a, Value b) {
#if defined(__clang__)
    return __builtin_shufflevector(a, b, A, B, C, D);
#else
    return __builtin_shuffle(a, b, Int{A, B, C, D});
#endif
  }
  // v where mask[lane] is non-zero, +0 elsewhere: on the bits, as keep_if.
  static Value keep_where(Value v, const std::uint8_t* mask) {
    const Int keep = Int{mask[0], mask[1], mask[2], mask[3]} != ints(0);
    return reinterpret_cast<Value>(reinterpret_cast<Int>(v) & keep);
  }

  static constexpr std::size_t kMaxPoints = std::size_t{1} << 31;
  static bool lanes_fit(std::size_t points) { return points < kMaxPoints; }
};
#endif

}  // namespace dp
