#pragma once
// A stable sort of keys below a bound known in advance (the cell indices of
// a grid), by counting, for the CPU. Each share of the keys counts its keys,
// one pass over the counts turns them into places, and each share puts its
// keys there in order: two passes over the keys, where a radix sort of
// 32-bit keys takes four and a merge of the threads' halves. The order of a
// stable sort is unique, so the result does not depend on the share count.
// The distinct keys and where each begins (their runs) fall out of the
// pass over the counts.
#include <omp.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace dp {

class CountingSort {
 public:
  // key[0 .. n), each below bound, in `shares` parts on as many threads:
  // sorted[q] is the q-th key in stable order and order[q] where it was;
  // run_key the distinct keys ascending, run_begin where each run begins
  // in sorted (one more entry: n).
  void sort(int shares, const std::uint32_t* key, std::size_t n, std::uint32_t bound, std::uint32_t* sorted, std::uint32_t* order,
            std::vector<std::uint32_t>& run_key, std::vector<std::uint32_t>& run_begin) {
    shares = std::max(1, shares);
    if (counts_.size() != static_cast<std::size_t>(shares) * bound) counts_.assign(static_cast<std::size_t>(shares) * bound, 0);
    lowest_.assign(shares, bound);
    highest_.assign(shares, 0);
    in_shares(shares, n, [&](int s, std::size_t begin, std::size_t end) { count(key, begin, end, counts_.data() + row(s, bound), s); });
    run_key.clear();
    run_begin.clear();
    const std::uint32_t low = *std::min_element(lowest_.begin(), lowest_.end());
    const std::uint32_t high = *std::max_element(highest_.begin(), highest_.end());
    std::uint32_t placed = 0;
    for (std::uint32_t k = low; k <= high && k < bound; ++k) {  // the counts become each share's first place for k
      const std::uint32_t first = placed;
      for (int s = 0; s < shares; ++s) {
        std::uint32_t& c = counts_[row(s, bound) + k];
        const std::uint32_t here = c;
        c = placed;
        placed += here;
      }
      if (placed > first) {
        run_key.push_back(k);
        run_begin.push_back(first);
      }
    }
    run_begin.push_back(static_cast<std::uint32_t>(n));
    in_shares(shares, n, [&](int s, std::size_t begin, std::size_t end) {
      std::uint32_t* place = counts_.data() + row(s, bound);
      for (std::size_t q = begin; q < end; ++q) {
        const std::uint32_t at = place[key[q]]++;
        sorted[at] = key[q];
        order[at] = static_cast<std::uint32_t>(q);
      }
    });
    for (int s = 0; s < shares && low <= high; ++s)  // zero again for the next sort
      std::fill(counts_.begin() + row(s, bound) + low, counts_.begin() + row(s, bound) + high + 1, 0u);
  }

 private:
  static std::size_t row(int s, std::uint32_t bound) { return static_cast<std::size_t>(s) * bound; }

  void count(const std::uint32_t* key, std::size_t begin, std::size_t end, std::uint32_t* c, int s) {
    std::uint32_t low = lowest_[s], high = highest_[s];
    for (std::size_t q = begin; q < end; ++q) {
      ++c[key[q]];
      low = std::min(low, key[q]);
      high = std::max(high, key[q]);
    }
    lowest_[s] = low;
    highest_[s] = high;
  }

  // body(s, begin, end) for share s of [0, n), the shares split as
  // schedule(static) would; any number of threads takes them in turn.
  template <class Body>
  static void in_shares(int shares, std::size_t n, const Body& body) {
    const auto share = [&](int s) { body(s, n * s / shares, n * (s + 1) / shares); };
    if (shares == 1) {
      share(0);
      return;
    }
#ifdef _OPENMP  // headers reach some files built without OpenMP, which never sort
#pragma omp parallel num_threads(shares)
#endif
    for (int s = omp_get_thread_num(); s < shares; s += omp_get_num_threads()) share(s);
  }

  std::vector<std::uint32_t> counts_;  // per share, per key: zero between sorts
  std::vector<std::uint32_t> lowest_, highest_;
};

}  // namespace dp
