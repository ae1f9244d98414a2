#pragma once
// Counter-based random numbers: every camera sample owns a stream keyed by
// (seed, pixel x, pixel y, sample index). A pixel's value then depends only
// on its own streams, never on which thread rendered it or in which order,
// so images are bit-identical for any thread count.
#include <cstdint>

namespace dp::render {

// A 64-bit finaliser (the SplitMix64 output function): every input bit
// affects every output bit, so nearby keys and counters give unrelated values.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

class RandomStream {
 public:
  RandomStream(std::uint64_t seed, std::uint32_t pixel_x, std::uint32_t pixel_y, std::uint32_t sample_index)
      : key_(mix64(mix64(mix64(seed + kGolden) ^ (std::uint64_t{pixel_x} << 32 | pixel_y)) ^ sample_index)) {}

  // Uniform in [0, 1): 24 random bits, exactly representable as a float.
  float uniform() { return static_cast<float>(mix64(key_ + ++counter_ * kGolden) >> 40) * 0x1p-24f; }

 private:
  // 2^64 / golden ratio: consecutive counters land far apart before mixing.
  static constexpr std::uint64_t kGolden = 0x9e3779b97f4a7c15ULL;
  std::uint64_t key_;
  std::uint64_t counter_ = 0;
};

}  // namespace dp::render
