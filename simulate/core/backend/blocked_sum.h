#pragma once
// The one summation order both backends use, so that a sum does not depend on
// thread count, schedule or backend. Values are cut into fixed blocks of
// kSumBlock elements. Within a block, lane l (of kSumLanes) adds the elements
// l, l + kSumLanes, l + 2 kSumLanes, ... in index order; the lanes are then
// folded as a binary tree (lane l takes lane l + 16, then l + 8, ... l + 1),
// which is what one GPU warp does with shuffles, so the GPU reads memory
// coalesced and still adds in exactly the CPU's order. The block sums are
// then summed the same way, as values of their own (block sums of block
// sums), until one value is left. On the GPU the first level is one thread
// block per block, and the thread block that finishes last adds the other
// levels in the same order (cuda_exec.cuh: sum_in_one_launch). Sums are
// carried in double.
#include <cstddef>

#include "backend/host_device.h"

namespace dp {

inline constexpr std::size_t kSumBlock = 1024;
inline constexpr unsigned kSumLanes = 32;

inline DP_HD std::size_t sum_block_count(std::size_t n) { return (n + kSumBlock - 1) / kSumBlock; }

// The sum of one block: its lanes folded as the warp folds them. The CPU's
// form: the block is walked once in index order, element i adding to lane
// i mod kSumLanes, which gives every lane its terms in the GPU lane's order
// while f reads memory contiguously (and can be vectorised). Inlined
// into the CPU launcher's loop, so that it runs in the loop's instruction
// set (cpu_isa.h).
template <class ValueAt>
DP_HD_INLINE double sum_block(std::size_t block, std::size_t n, const ValueAt& f) {
  double lane[kSumLanes] = {};
  const std::size_t begin = block * kSumBlock;
  const std::size_t end = begin + kSumBlock < n ? begin + kSumBlock : n;
  std::size_t i = begin;
  for (; i + kSumLanes <= end; i += kSumLanes)
    for (unsigned l = 0; l < kSumLanes; ++l) lane[l] += static_cast<double>(f(i + l));
  for (unsigned l = 0; i < end; ++i, ++l) lane[l] += static_cast<double>(f(i));
  for (unsigned offset = kSumLanes / 2; offset > 0; offset /= 2)
    for (unsigned l = 0; l < offset; ++l) lane[l] += lane[l + offset];
  return lane[0];
}

// What runs after a sum_into by default: nothing.
struct NothingAfterSum {
  DP_HD void operator()(std::size_t) const {}
};

// The values of one level of block sums, as a ValueAt.
struct BlockSums {
  const double* sums;
  DP_HD double operator()(std::size_t i) const { return sums[i]; }
};

// The scratch of a sum that keeps its levels in one buffer (sum_into): one
// value's room for the count of finished blocks (cuda_exec.cuh), which must
// be zero before the buffer's first sum (a zero-filled buffer) and is zero
// again after each, then every level of block sums from the first one's
// sum_block_count(n) values down to (excluding) the final one.
inline DP_HD std::size_t sum_scratch_count(std::size_t n) {
  std::size_t total = 1;
  for (std::size_t blocks = sum_block_count(n); blocks > 1; blocks = sum_block_count(blocks)) total += blocks;
  return total;
}

}  // namespace dp
