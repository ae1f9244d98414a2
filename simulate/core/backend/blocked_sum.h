#pragma once
// The one summation order both backends use, so that a sum does not depend on
// thread count, schedule or backend: values are summed in index order within
// fixed blocks of kSumBlock elements, then the block sums in block order.
// Sums are carried in double.
#include <cstddef>

#include "backend/host_device.h"

namespace dp {

inline constexpr std::size_t kSumBlock = 1024;

inline DP_HD std::size_t sum_block_count(std::size_t n) { return (n + kSumBlock - 1) / kSumBlock; }

// Sums the values f(i) of one block, in index order.
template <class ValueAt>
DP_HD double sum_block(std::size_t block, std::size_t n, const ValueAt& f) {
  std::size_t begin = block * kSumBlock;
  std::size_t end = begin + kSumBlock < n ? begin + kSumBlock : n;
  double s = 0.0;
  for (std::size_t i = begin; i < end; ++i) s += static_cast<double>(f(i));
  return s;
}

}  // namespace dp
