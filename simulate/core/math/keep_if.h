#pragma once
// Selections on a value's bits. keep_if(v, bit) is v where `bit` (0 or 1)
// is set and +0 where not: an integer and on v's bits, no floating-point
// operation. A kernel may then compute v for every element and select
// without branching: g++ moves no floating-point operation (which may
// trap) out from under a condition, and sinks one used by a plain
// `bit ? v : 0` into the branch that uses it, which keeps the branch and
// leaves the loop scalar.
#include <cstdint>
#include <cstring>

#include "backend/host_device.h"

namespace dp {

// A float's or double's bits as the signed integer of its width, and back.
// Non-negative floats (and +inf) order as their bits do as integers.
DP_HD_INLINE std::int32_t bits_of(float v) {
#if defined(__CUDA_ARCH__)
  return __float_as_int(v);
#else
  std::int32_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
#endif
}

DP_HD_INLINE std::int64_t bits_of(double v) {
#if defined(__CUDA_ARCH__)
  return __double_as_longlong(v);
#else
  std::int64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
#endif
}

DP_HD_INLINE float from_bits(std::int32_t b) {
#if defined(__CUDA_ARCH__)
  return __int_as_float(b);
#else
  float v;
  std::memcpy(&v, &b, sizeof v);
  return v;
#endif
}

DP_HD_INLINE double from_bits(std::int64_t b) {
#if defined(__CUDA_ARCH__)
  return __longlong_as_double(b);
#else
  double v;
  std::memcpy(&v, &b, sizeof v);
  return v;
#endif
}

// All ones where `bit` (0 or 1) is set, zero where not, of V's width.
template <class V>
DP_HD_INLINE auto mask_of(unsigned bit) {
  using Bits = decltype(bits_of(V{}));
  return static_cast<Bits>(Bits{0} - static_cast<Bits>(bit));
}

template <class V>
DP_HD_INLINE V keep_if(V v, unsigned bit) {
  return from_bits(bits_of(v) & mask_of<V>(bit));
}

// a where `bit` (0 or 1) is set, b where not, on their bits as keep_if
// (adding keep_if(b, !bit) would turn a = -0 into +0).
template <class V>
DP_HD_INLINE V pick_if(unsigned bit, V a, V b) {
  const auto mask = mask_of<V>(bit);
  return from_bits((bits_of(a) & mask) | (bits_of(b) & ~mask));
}

}  // namespace dp
