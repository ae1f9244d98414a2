#pragma once
// How many grid points the sampling code (staggered_sampling.h) works on at
// once. It is written once over a lanes policy: OneLane, for every caller
// and for all GPU work, or VectorLanes, four (SSE) or eight (AVX)
// consecutive points of an x row, which the CPU launcher uses for the
// semi-Lagrangian pass (MacCormack's correction pass stays one point at a
// time) and, four at a time, for the multigrid transfers
// (multigrid_mcadams2010.h). A back-trace
// is some 400 scalar instructions around data-dependent gathers, which g++
// does not vectorise by itself on baseline x86-64, and it was 40 % of the
// CPU air step (docs/benchmarks.md). Both policies run the same
// floating-point operations in the same order on each point, so for
// finite velocity fields the results are the same bit for bit (tested).
// (With a non-finite velocity a group of lanes may take the general
// sampling path where one point would take the fixed-weight one, and
// 0 * inf differs from not multiplying; the step stops on such a field.)
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <utility>

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
// Registers of N floats, N ints, N / 2 doubles (g++ takes no vector_size
// that depends on a template parameter).
template <int N>
struct LaneRegisters;
template <>
struct LaneRegisters<4> {
  typedef float Real __attribute__((vector_size(16)));
  typedef int Int __attribute__((vector_size(16)));
  typedef double Pairs __attribute__((vector_size(16)));
};
template <>
struct LaneRegisters<8> {
  typedef float Real __attribute__((vector_size(32)));
  typedef int Int __attribute__((vector_size(32)));
  typedef double Pairs __attribute__((vector_size(32)));
};

// N consecutive points (4 or 8), as GCC/Clang vector extensions, in host
// code only (nvcc's host pass takes them too, so the CPU backend's functors
// are the same in .cu and .cpp files): FourLanes, SSE registers, in both of
// the launcher's copies; EightLanes, AVX registers, in its AVX2 copy only
// (cpu_isa.h), which is where it calls eight_along_x. Every member is
// forced inline, so that it takes the instruction set of the loop it runs
// in. Lattice positions are 32-bit lanes: the CPU launcher takes this path
// only for lattices of fewer than 2^31 points (lanes_fit).
template <int N>
struct VectorLanes {
  using Real = typename LaneRegisters<N>::Real;
  using Int = typename LaneRegisters<N>::Int;
  using Value = Real;
  using Index = Int;
  static constexpr int kCount = N;

  DP_HOST_INLINE static Real reals(float v) { return broadcast<Real>(v); }
  DP_HOST_INLINE static Int ints(int v) { return broadcast<Int>(v); }
  DP_HOST_INLINE static Int truncate(Real v) { return __builtin_convertvector(v, Int); }
  DP_HOST_INLINE static Real to_real(Int v) { return __builtin_convertvector(v, Real); }
  DP_HOST_INLINE static Index to_index(Int v) { return v; }
  DP_HOST_INLINE static Int consecutive(int first) { return first + lane_numbers(std::make_integer_sequence<int, N>{}); }
  DP_HOST_INLINE static Value weight(Real t) { return t; }
  DP_HOST_INLINE static Value load(const float* p, Index i) {
    Value v;
    for (int l = 0; l < N; ++l) v[l] = p[i[l]];
    return v;
  }
  DP_HOST_INLINE static Value load_consecutive(const float* p, std::size_t first) { return load_row(p + first); }
  // OneLane::corners for N points: each lane's position is taken out of
  // the vector once, and its eight corners are loaded at fixed offsets from
  // it, rather than every corner's position being formed in a vector and
  // taken apart lane by lane (a third of the back-trace's instructions).
  struct Corners {
    Value v[8];
  };
  DP_HOST_INLINE static Corners corners(const float* p, Index c, std::ptrdiff_t di, std::ptrdiff_t dj, std::ptrdiff_t dk) {
    const float* at[N];
    for (int l = 0; l < N; ++l) at[l] = p + c[l];
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
  DP_HOST_INLINE static Value gather(const float* const* at, std::ptrdiff_t d) {
    Value v;
    for (int l = 0; l < N; ++l) v[l] = at[l][d];
    return v;
  }
  // Each lane's at[d] into `first` and at[d + 1] into `second`.
  DP_HOST_INLINE static void gather_pair(const float* const* at, std::ptrdiff_t d, Value& first, Value& second) {
    typename LaneRegisters<N>::Pairs low, high;  // lanes 0 .. N/2 - 1, and the rest
    for (int l = 0; l < N / 2; ++l) {  // clang takes no address of a vector's lane
      low[l] = two_floats(at[l] + d);
      high[l] = two_floats(at[N / 2 + l] + d);
    }
    first = every_other<0>(reinterpret_cast<Value>(low), reinterpret_cast<Value>(high), std::make_integer_sequence<int, N>{});
    second = every_other<1>(reinterpret_cast<Value>(low), reinterpret_cast<Value>(high), std::make_integer_sequence<int, N>{});
  }
  DP_HOST_INLINE static void store(float* p, Value v) { std::memcpy(p, &v, sizeof v); }
  // p[0 .. N - 1], one unaligned load.
  DP_HOST_INLINE static Value load_row(const float* p) {
    Value v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  // Lanes I... of the 2N of a then b.
  template <int... I>
  DP_HOST_INLINE static Value pick(Value a, Value b) {
    static_assert(sizeof...(I) == N, "one source lane per lane");
#if defined(__clang__)
    return __builtin_shufflevector(a, b, I...);
#else
    return __builtin_shuffle(a, b, Int{I...});
#endif
  }
  // v where mask[lane] is non-zero, +0 elsewhere: on the bits, as keep_if.
  DP_HOST_INLINE static Value keep_where(Value v, const std::uint8_t* mask) {
    Int m;
    for (int l = 0; l < N; ++l) m[l] = mask[l];
    return reinterpret_cast<Value>(reinterpret_cast<Int>(v) & (m != ints(0)));
  }

  static constexpr std::size_t kMaxPoints = std::size_t{1} << 31;
  static bool lanes_fit(std::size_t points) { return points < kMaxPoints; }

 private:
  template <class V, class S>
  DP_HOST_INLINE static V broadcast(S v) {
    V lanes;
    for (int l = 0; l < N; ++l) lanes[l] = v;
    return lanes;
  }
  // p[0] and p[1] as the bits of one double: one 8-byte load.
  DP_HOST_INLINE static double two_floats(const float* p) {
    double both;
    std::memcpy(&both, p, sizeof both);
    return both;
  }
  template <int... L>
  DP_HOST_INLINE static Int lane_numbers(std::integer_sequence<int, L...>) { return Int{L...}; }
  // Lanes First, First + 2, ... of the 2N of a then b.
  template <int First, int... L>
  DP_HOST_INLINE static Value every_other(Value a, Value b, std::integer_sequence<int, L...>) {
    return pick<(2 * L + First)...>(a, b);
  }
};
using FourLanes = VectorLanes<4>;
using EightLanes = VectorLanes<8>;
#endif

}  // namespace dp
