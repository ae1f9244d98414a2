#pragma once
// v where `bit` (0 or 1) is set, +0 where not: an integer and on v's bits,
// no floating-point operation. A kernel may then compute v for every
// element and select without branching: g++ moves no floating-point
// operation (which may trap) out from under a condition, and sinks one
// used by a plain `bit ? v : 0` into the branch that uses it, which keeps
// the branch and leaves the loop scalar.
#include <cstdint>
#include <cstring>

#include "backend/host_device.h"

namespace dp {

DP_HD_INLINE float keep_if(float v, unsigned bit) {
#if defined(__CUDA_ARCH__)
  return __uint_as_float(__float_as_uint(v) & (0u - bit));
#else
  std::uint32_t u;
  std::memcpy(&u, &v, sizeof u);
  u &= 0u - bit;
  float kept;
  std::memcpy(&kept, &u, sizeof kept);
  return kept;
#endif
}

DP_HD_INLINE double keep_if(double v, unsigned bit) {
#if defined(__CUDA_ARCH__)
  return __longlong_as_double(__double_as_longlong(v) & (0ll - static_cast<long long>(bit)));
#else
  std::uint64_t u;
  std::memcpy(&u, &v, sizeof u);
  u &= std::uint64_t{0} - bit;
  double kept;
  std::memcpy(&kept, &u, sizeof kept);
  return kept;
#endif
}

// a where `bit` (0 or 1) is set, b where not, on their bits as keep_if
// (adding keep_if(b, !bit) would turn a = -0 into +0).
DP_HD_INLINE float pick_if(unsigned bit, float a, float b) {
#if defined(__CUDA_ARCH__)
  return bit ? a : b;
#else
  std::uint32_t x, y;
  std::memcpy(&x, &a, sizeof x);
  std::memcpy(&y, &b, sizeof y);
  const std::uint32_t mask = 0u - bit;
  const std::uint32_t z = (x & mask) | (y & ~mask);
  float picked;
  std::memcpy(&picked, &z, sizeof picked);
  return picked;
#endif
}

DP_HD_INLINE double pick_if(unsigned bit, double a, double b) {
#if defined(__CUDA_ARCH__)
  return bit ? a : b;
#else
  std::uint64_t x, y;
  std::memcpy(&x, &a, sizeof x);
  std::memcpy(&y, &b, sizeof y);
  const std::uint64_t mask = std::uint64_t{0} - bit;
  const std::uint64_t z = (x & mask) | (y & ~mask);
  double picked;
  std::memcpy(&picked, &z, sizeof picked);
  return picked;
#endif
}

}  // namespace dp
