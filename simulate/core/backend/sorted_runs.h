#pragma once
// Runs of equal keys in a sorted key array, on either backend: the distinct
// keys in order and where each run begins. Kernels that gather per key (a
// cell gathering the pairs that name it) then run over the keys that occur
// instead of over every possible key, and find their entries without a
// search. Built from a scan of "a run starts here" flags, so the result is
// the same for every thread count and on both backends.
#include <cstddef>
#include <cstdint>

#include "backend/host_device.h"

namespace dp {

// A run of equal keys starts at q.
struct KeyChanges {
  const std::uint32_t* key;  // sorted
  DP_HD bool operator()(std::size_t q) const { return q == 0 || key[q] != key[q - 1]; }
};

template <class StartsAt>
struct FlagRunStarts {
  StartsAt starts_at;
  std::uint32_t* start;
  DP_HD void operator()(std::size_t q) const { start[q] = starts_at(q) ? 1u : 0u; }
};

struct ScatterRuns {
  const std::uint32_t* key;
  const std::uint32_t* start;
  const std::uint32_t* run_before;  // exclusive scan of `start`
  std::size_t n;
  std::uint32_t* run_key;
  std::uint32_t* run_begin;  // runs + 1 entries
  DP_HD void operator()(std::size_t q) const {
    if (start[q]) {
      run_key[run_before[q]] = key[q];
      run_begin[run_before[q]] = static_cast<std::uint32_t>(q);
    }
    if (q + 1 == n) run_begin[run_before[q] + start[q]] = static_cast<std::uint32_t>(n);
  }
};

// f(key) for each listed key: a per-key kernel, or the values of a sum,
// restricted to a list.
template <class F>
struct AtKeys {
  const std::uint32_t* key;
  F f;
  DP_HD auto operator()(std::size_t r) const { return f(key[r]); }
};
template <class F>
AtKeys<F> at_keys(const std::uint32_t* key, const F& f) { return AtKeys<F>{key, f}; }

template <class Exec>
struct SortedRuns {
  template <class T>
  using Buffer = typename Exec::template Buffer<T>;
  std::size_t count = 0;           // number of distinct keys
  Buffer<std::uint32_t> key;       // distinct keys, ascending (count)
  Buffer<std::uint32_t> begin;     // run r is [begin[r], begin[r + 1]) of the sorted array (count + 1)

  void build(const Exec& exec, const Buffer<std::uint32_t>& sorted_key) { build_at(exec, sorted_key, KeyChanges{Exec::ptr(sorted_key)}); }

  // Runs that start wherever starts_at(q) holds (it must at q = 0), each
  // keyed by its first entry's key: finer runs than equal keys give, such
  // as stretches of consecutive keys.
  template <class StartsAt>
  void build_at(const Exec& exec, const Buffer<std::uint32_t>& sorted_key, const StartsAt& starts_at) {
    const std::size_t n = sorted_key.size();
    count = 0;
    key.resize(0);
    begin.assign(1, 0);
    if (n == 0) return;
    start_.resize(n);
    exec.parallel_for(n, FlagRunStarts<StartsAt>{starts_at, Exec::ptr(start_)});
    exec.exclusive_scan(start_, before_);
    count = Exec::download_one(before_, n - 1) + Exec::download_one(start_, n - 1);
    key.resize(count);
    begin.resize(count + 1);
    exec.parallel_for(n, ScatterRuns{Exec::ptr(sorted_key), Exec::ptr(start_), Exec::ptr(before_), n, Exec::ptr(key),
                                     Exec::ptr(begin)});
  }

  // The number of runs that start before entry q (the run holding a run's
  // first entry q is runs_before()[q]).
  const std::uint32_t* runs_before() const { return Exec::ptr(before_); }

 private:
  Buffer<std::uint32_t> start_, before_;
};

}  // namespace dp
