#pragma once
// Deterministic stochastic rounding. A coupling step's change to a
// particle's mass (a fraction of one mass unit) or temperature (often below
// one float ulp at 300 K) would be lost to rounding to nearest every step;
// rounding up with probability equal to the remainder keeps the expected
// change exact. The coin is a hash of the particle's id and the step, so
// runs are reproducible and independent of thread count and backend.
#include <cmath>
#include <cstdint>

#include "backend/host_device.h"

namespace dp {

// A 64-bit mix (splitmix64 finaliser) of id and step, top 32 bits.
DP_HD inline std::uint32_t rounding_hash(std::uint32_t id, std::uint64_t step) {
  std::uint64_t x = (static_cast<std::uint64_t>(id) << 32) ^ step ^ 0x9E3779B97F4A7C15ull;
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ull;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebull;
  x ^= x >> 31;
  return static_cast<std::uint32_t>(x >> 32);
}

// `value` rounded to one of its two neighbouring floats, the farther one
// with probability proportional to closeness.
DP_HD inline float stochastic_round_to_float(double value, std::uint32_t coin) {
  const float nearest = static_cast<float>(value);
  const double d = value - static_cast<double>(nearest);
  if (d == 0) return nearest;
  const float other = nextafterf(nearest, d > 0 ? INFINITY : -INFINITY);
  const double p = fabs(d) / fabs(static_cast<double>(other) - static_cast<double>(nearest));
  return coin * (1.0 / 4294967296.0) < p ? other : nearest;
}

}  // namespace dp
