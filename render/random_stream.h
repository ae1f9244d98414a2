#pragma once
// Random numbers for one camera sample, keyed by (seed, pixel x, pixel y,
// sample index). A pixel's value then depends only on its own streams,
// never on which thread rendered it or in which order, so images are
// bit-identical for any thread count.
//
// Two kinds:
//  * independent: every number drawn from a counter-based hash (plain Monte
//    Carlo; error falls as N^-1/2);
//  * sobol: the pixel's samples are an Owen-scrambled Sobol (0,2)-sequence
//    per dimension pair, with the sample order shuffled per pair so pairs
//    do not correlate (Burley 2020, "Practical Hash-based Owen Scrambling",
//    JCGT 9(4)). Still unbiased, but stratified: lower error at equal spp,
//    as in production renderers.
// Callers draw 1D values with uniform() and 2D points with uniform2(); each
// call is a fresh dimension (pair).
#include <cstdint>

#include "sampling.h"

namespace dp::render {

// A 64-bit finaliser (the SplitMix64 output function): every input bit
// affects every output bit, so nearby keys and counters give unrelated values.
constexpr std::uint64_t mix64(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

enum class SampleSequence { Independent, Sobol };

class RandomStream {
 public:
  RandomStream(std::uint64_t seed, std::uint32_t pixel_x, std::uint32_t pixel_y, std::uint32_t sample_index,
               SampleSequence sequence = SampleSequence::Independent)
      : key_(mix64(mix64(seed + kGolden) ^ (std::uint64_t{pixel_x} << 32 | pixel_y))),
        sample_(sample_index),
        sequence_(sequence) {
    if (sequence_ == SampleSequence::Independent) key_ = mix64(key_ ^ sample_index);
  }

  // Uniform in [0, 1): 24 random bits, exactly representable as a float.
  float uniform() {
    const std::uint64_t dimension = ++counter_;
    if (sequence_ == SampleSequence::Independent) return to_unit(static_cast<std::uint32_t>(mix64(key_ + dimension * kGolden) >> 32));
    const std::uint32_t index = shuffled_index(dimension);
    return to_unit(nested_uniform_scramble(reverse_bits(index), scramble_seed(dimension, 0)));
  }

  Sample2 uniform2() {
    if (sequence_ == SampleSequence::Independent) {
      const float a = uniform();
      return {a, uniform()};
    }
    const std::uint64_t dimension = ++counter_;
    const std::uint32_t index = shuffled_index(dimension);
    return {to_unit(nested_uniform_scramble(reverse_bits(index), scramble_seed(dimension, 1))),
            to_unit(nested_uniform_scramble(sobol_second_dimension(index), scramble_seed(dimension, 2)))};
  }

 private:
  // 2^64 / golden ratio: consecutive counters land far apart before mixing.
  static constexpr std::uint64_t kGolden = 0x9e3779b97f4a7c15ULL;

  static float to_unit(std::uint32_t bits) { return static_cast<float>(bits >> 8) * 0x1p-24f; }

  static constexpr std::uint32_t reverse_bits(std::uint32_t x) {
    x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
    x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
    return (x >> 16) | (x << 16);
  }
  // Burley 2020, Listing 1: a hash that permutes x as an Owen scramble of
  // its reversed bits (Laine & Karras 2011, with better constants).
  static constexpr std::uint32_t laine_karras_permutation(std::uint32_t x, std::uint32_t seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
  }
  static constexpr std::uint32_t nested_uniform_scramble(std::uint32_t x, std::uint32_t seed) {
    return reverse_bits(laine_karras_permutation(reverse_bits(x), seed));
  }
  // Sobol's second dimension (primitive polynomial x + 1): direction
  // numbers v_0 = 2^31, v_j = v_{j-1} xor (v_{j-1} >> 1); the result is the
  // xor of v_j over the index's set bits, looked up a byte at a time.
  struct SobolBytes {
    std::uint32_t table[4][256] = {};
    constexpr SobolBytes() {
      std::uint32_t v[32] = {};
      v[0] = 1u << 31;
      for (int j = 1; j < 32; ++j) v[j] = v[j - 1] ^ (v[j - 1] >> 1);
      for (int b = 0; b < 4; ++b)
        for (int byte = 0; byte < 256; ++byte)
          for (int bit = 0; bit < 8; ++bit)
            if (byte & (1 << bit)) table[b][byte] ^= v[8 * b + bit];
    }
  };
  static std::uint32_t sobol_second_dimension(std::uint32_t index) {
    static constexpr SobolBytes bytes;
    return bytes.table[0][index & 0xff] ^ bytes.table[1][(index >> 8) & 0xff] ^ bytes.table[2][(index >> 16) & 0xff] ^
           bytes.table[3][index >> 24];
  }
  std::uint32_t scramble_seed(std::uint64_t dimension, std::uint64_t which) const {
    return static_cast<std::uint32_t>(mix64(key_ ^ (dimension * 4 + which) * kGolden));
  }
  // The pixel's sample order, shuffled per dimension (Burley 2020, Sec. 3).
  std::uint32_t shuffled_index(std::uint64_t dimension) const {
    return nested_uniform_scramble(sample_, scramble_seed(dimension, 3));
  }

  std::uint64_t key_;
  std::uint32_t sample_;
  SampleSequence sequence_;
  std::uint64_t counter_ = 0;
};

}  // namespace dp::render
