#pragma once
// CPU backend: OpenMP threads for per-element kernels, CCCL Thrust (compiled by
// the host compiler, OpenMP system) for sort and scan. Deterministic: kernels
// gather and write only their own element (or, in MarkLiquidCells, the same
// value to a shared byte), sorts are stable, sums use the
// fixed blocked order of blocked_sum.h.
#include <omp.h>
#include <thrust/scan.h>
#include <thrust/sort.h>
#include <thrust/system/omp/execution_policy.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

#include "backend/blocked_sum.h"
#include "backend/cpu_isa.h"

namespace dp {

// Whether functor F offers four_along_x(i, j, k) and lanes_fit()
// (sample_lanes.h). A trait, not a concept: nvcc compiles this header as
// C++17 where .cu tests run the CPU backend beside the GPU one.
template <class F, class = void>
struct TakesFourAlongX : std::false_type {};
template <class F>
struct TakesFourAlongX<F, std::void_t<decltype(std::declval<const F&>().four_along_x(0, 0, 0)),
                                      decltype(static_cast<bool>(std::declval<const F&>().lanes_fit()))>>
    : std::true_type {};

// Whether functor F offers eight_along_x(i, j, k) as well: eight points as
// AVX lanes, which only the launcher's AVX2 copy calls.
template <class F, class = void>
struct TakesEightAlongX : std::false_type {};
template <class F>
struct TakesEightAlongX<F, std::void_t<decltype(std::declval<const F&>().eight_along_x(0, 0, 0))>> : TakesFourAlongX<F> {};

// The copy of the launcher's loops that runs (cpu_isa.h, CpuExec::run),
// handed to each loop: the AVX2 copy's rows may take eight lanes at once.
struct BaselineCopy {
  static constexpr bool kEightLanes = false;
};
struct Avx2Copy {
  static constexpr bool kEightLanes = true;
};

// Whether functor F offers whole_row(nx, j, k), for points 0 .. nx - 1 of
// row (j, k) at once: a functor whose per-point branches are the same along
// a row decides them once there, and its inner loop vectorises.
template <class F, class = void>
struct TakesWholeRows : std::false_type {};
template <class F>
struct TakesWholeRows<F, std::void_t<decltype(std::declval<const F&>().whole_row(0, 0, 0))>> : std::true_type {};

// Whether functor F offers whole_range(begin, end), for elements begin ..
// end - 1 of a 1-D pass at once: one whose output pointers g++ cannot tell
// apart from its inputs takes them there as restrict parameters, and its
// loop vectorises without a run-time overlap test per pair of pointers.
template <class F, class = void>
struct TakesWholeRanges : std::false_type {};
template <class F>
struct TakesWholeRanges<F, std::void_t<decltype(std::declval<const F&>().whole_range(std::size_t{}, std::size_t{}))>>
    : std::true_type {};

// Whether functor F offers row_max(nx, j, k), the largest of f(i, j, k)
// over row (j, k) at once: a maximum g++ vectorises only in a form that
// holds for F's values alone (CellOutflowSpeed takes it on the bits).
template <class F, class = void>
struct TakesRowMax : std::false_type {};
template <class F>
struct TakesRowMax<F, std::void_t<decltype(std::declval<const F&>().row_max(0, 0, 0))>> : std::true_type {};

// The largest f(i, j, k) of row `row` = j + ny k of a box nx wide, or -inf.
template <class F>
struct RowMaxAt {
  F f;
  int nx, ny;
  DP_HD_INLINE float operator()(std::size_t row) const {
    const int j = static_cast<int>(row % static_cast<std::size_t>(ny)), k = static_cast<int>(row / static_cast<std::size_t>(ny));
    if constexpr (TakesRowMax<F>::value) {
      return f.row_max(nx, j, k);
    } else {
      float m = -std::numeric_limits<float>::infinity();
      for (int i = 0; i < nx; ++i) m = std::max(m, static_cast<float>(f(i, j, k)));
      return m;
    }
  }
};

// The launcher's loops over a range, each one a functor whose call inlines
// into both copies (CpuExec::run): elements begin .. end - 1 of a 1-D pass,
// rows begin .. end - 1 of a box, or blocks begin .. end - 1 of a sum.
template <class F>
struct ElementLoop {
  F f;  // by value, run from a local copy (CpuExec::run_local)
  std::size_t begin, end;
  template <class Copy>
  DP_HD_INLINE void operator()(Copy) const {
    if constexpr (TakesWholeRanges<F>::value) {
      f.whole_range(begin, end);
    } else {
      for (std::size_t i = begin; i < end; ++i) f(i);
    }
  }
};

template <class F>
struct RowLoop {
  F f;
  int nx, ny;
  std::int64_t begin, end;
  bool lanes;  // hand whole groups of lanes to f.four_along_x, f.eight_along_x (sample_lanes.h)
  template <class Copy>
  DP_HD_INLINE void operator()(Copy) const {
    for (std::int64_t r = begin; r < end; ++r) {
      const int j = static_cast<int>(r % ny), k = static_cast<int>(r / ny);
      if constexpr (TakesWholeRows<F>::value) {
        f.whole_row(nx, j, k);
        continue;
      }
      int i = 0;
      if constexpr (TakesFourAlongX<F>::value) {
        if (lanes) {
          if constexpr (Copy::kEightLanes && TakesEightAlongX<F>::value) {
            for (; i + 8 <= nx; i += 8) f.eight_along_x(i, j, k);
          }
          for (; i + 4 <= nx; i += 4) f.four_along_x(i, j, k);
        }
      }
      for (; i < nx; ++i) f(i, j, k);
    }
  }
};

// The first i of elements begin .. end - 1 where pred holds, or end, into
// *first. Each block is first tested whole with an or, no exit inside, a
// loop g++ vectorises where pred allows; only a block where pred holds
// somewhere is searched element by element.
template <class Pred>
struct FirstLoop {
  Pred pred;
  std::size_t begin, end;
  std::size_t* first;
  template <class Copy>
  DP_HD_INLINE void operator()(Copy) const {
    constexpr std::size_t kBlock = 1024;
    for (std::size_t b = begin; b < end; b += kBlock) {
      const std::size_t e = end - b < kBlock ? end : b + kBlock;
      unsigned any = 0;
      for (std::size_t i = b; i < e; ++i) any |= pred(i) ? 1u : 0u;
      if (any) {
        std::size_t i = b;
        while (!pred(i)) ++i;
        *first = i;
        return;
      }
    }
    *first = end;
  }
};

template <class ValueAt>
struct BlockSumLoop {
  ValueAt f;
  std::size_t n;
  double* sums;
  std::size_t begin, end;
  template <class Copy>
  DP_HD_INLINE void operator()(Copy) const {
    for (std::size_t b = begin; b < end; ++b) sums[b] = sum_block(b, n, f);
  }
};

class CpuExec {
 public:
  template <class T>
  using Buffer = std::vector<T>;

  // Convergence checks of iterative solvers after every iteration: on the
  // CPU a check costs nothing and an iteration past convergence a lot.
  static constexpr int kIterationsPerCheck = 1;

  // A pass and the dot product of its result, fused into one sum where the
  // sum's f writes the element: on the CPU one walk over memory instead of
  // two (and one thread wake-up).
  static constexpr bool kFusesPassesIntoSums = true;

  // Buffers are host memory: the host reads an element without a copy or a
  // wait (ParticleGrid::find_ranges reads the lowest and highest keys).
  static constexpr bool kBuffersInHostMemory = true;

  // A pass costs its walk over memory, not a launch: two passes that the
  // CPU vectorises beat one that it does not (the multigrid's separable
  // transfers, CycleLayout).
  static constexpr bool kPassCostsALaunch = false;

  // Passes over at most this many elements gain nothing from in_one_block
  // here: below kSerialBelow they already run on the calling thread.
  static constexpr std::size_t kOneBlockElements = 0;

  explicit CpuExec(int threads, CpuIsa isa = detect_cpu_isa()) : threads_(threads > 0 ? threads : 1), isa_(isa) {
    omp_set_num_threads(threads_);
  }

  int threads() const { return threads_; }
  CpuIsa isa() const { return isa_; }
  static constexpr const char* name() { return "cpu"; }

  template <class T>
  static T* ptr(Buffer<T>& b) { return b.data(); }
  template <class T>
  static const T* ptr(const Buffer<T>& b) { return b.data(); }
  template <class T>
  static void upload(Buffer<T>& dst, const std::vector<T>& src) { dst = src; }
  template <class T>
  static T download_one(const Buffer<T>& src, std::size_t i) { return src[i]; }
  template <class T>
  static std::vector<T> download(const Buffer<T>& src) { return src; }

  // Loops over fewer elements than this run on the calling thread: waking
  // the other threads for one pass costs tens of microseconds (a futex
  // round trip, more under a hypervisor), more than a pass over a coarse
  // multigrid level (8^3 = 512 cells) or a short list takes. 2048 cells of
  // the cheapest grid pass cost about that much, while 2048 particles of an
  // SPH pass over ~50 neighbours each cost milliseconds: at 32K the glass
  // preview's 8300 particles ran every particle pass on one thread
  // (docs/benchmarks.md, "Particle passes on both cores"). Each element is
  // computed alone either way, so results do not change.
  static constexpr std::size_t kSerialBelow = std::size_t{1} << 11;

  // Calls f(i) for every i in [0, n).
  template <class F>
  void parallel_for(std::size_t n, const F& f) const {
    if (!uses_threads(n)) {
      run(ElementLoop<F>{f, 0, n});
      return;
    }
#pragma omp parallel num_threads(threads_)
    {
      const Share s = share_of(n);
      run(ElementLoop<F>{f, s.begin, s.end});
    }
  }

  // Calls f(i) for every i in [0, n) whose elements differ in cost (a
  // cell's loop over its pairs): the threads' contiguous shares hold equal
  // work, work_before(i) being that of elements 0 .. i-1 (non-decreasing,
  // work_before(n) the total, in units of a cheap element, so that small
  // totals run on the calling thread). By element count, the texels' 1860
  // cells of SCA Logo Tex, with 8M pairs between them, ran on one thread.
  template <class W, class F>
  void parallel_for_by_work(std::size_t n, const W& work_before, const F& f) const {
    if (!uses_threads(work_before(n))) {
      run(ElementLoop<F>{f, 0, n});
      return;
    }
#pragma omp parallel num_threads(threads_)
    {
      const Share s = work_share_of(n, work_before);
      run(ElementLoop<F>{f, s.begin, s.end});
    }
  }

  // Calls f(i, j, k) for every point of an nx x ny x nz box: threads take
  // whole x rows, so a functor is handed its coordinates without dividing a
  // linear index and its inner loop runs along contiguous memory.
  // A functor with four_along_x(i, j, k) (and lanes_fit() true) is handed
  // four points of a row at a time (sample_lanes.h), and in the AVX2 copy
  // eight at a time where it has eight_along_x, the rest one by one; one
  // with whole_row(nx, j, k) whole rows.
  template <class F>
  void parallel_for_3d(int nx, int ny, int nz, const F& f) const {
    const std::int64_t rows = static_cast<std::int64_t>(ny) * nz;
    bool lanes = false;
    if constexpr (TakesFourAlongX<F>::value) lanes = f.lanes_fit();
    if (!uses_threads(static_cast<std::size_t>(rows) * nx)) {
      run(RowLoop<F>{f, nx, ny, 0, rows, lanes});
      return;
    }
#pragma omp parallel num_threads(threads_)
    {
      const Share s = share_of(static_cast<std::size_t>(rows));
      run(RowLoop<F>{f, nx, ny, static_cast<std::int64_t>(s.begin), static_cast<std::int64_t>(s.end), lanes});
    }
  }

  // Calls f(s, i) for s = 0 .. sweeps-1 and every i in [0, n), all of pass
  // s before any of pass s + 1.
  template <class F>
  void parallel_sweeps(std::size_t n, int sweeps, const F& f) const {
    for (int s = 0; s < sweeps; ++s) parallel_for(n, [&](std::size_t i) { f(s, i); });
  }

  // body(exec) for an executor whose passes run in one GPU thread block
  // there (CudaExec::in_one_block); here that executor is this launcher,
  // which runs small passes on the calling thread alone anyway.
  template <class Body>
  void in_one_block(const Body& body) const {
    body(*this);
  }

  // Stable sort of (keys, values) by key.
  template <class K, class V>
  void sort_by_key(Buffer<K>& keys, Buffer<V>& values) const {
    thrust::stable_sort_by_key(thrust::omp::par, keys.data(), keys.data() + keys.size(), values.data());
  }

  template <class T>
  void exclusive_scan(const Buffer<T>& in, Buffer<T>& out) const {
    out.resize(in.size());
    thrust::exclusive_scan(thrust::omp::par, in.data(), in.data() + in.size(), out.data());
  }

  // Sum of f(i) over [0, n) in the blocked order (see blocked_sum.h). Both
  // backends call f exactly once per i, so f may also write element i (a
  // pass and its dot product fused).
  template <class ValueAt>
  double sum(std::size_t n, const ValueAt& f) const {
    if (n == 0) return 0.0;
    std::vector<double> level(sum_block_count(n));
    // Threads by the n elements summed, not by the few blocks they fill.
    if (!uses_threads(n)) {
      run(BlockSumLoop<ValueAt>{f, n, level.data(), 0, level.size()});
    } else {
#pragma omp parallel num_threads(threads_)
      {
        const Share s = share_of(level.size());
        run(BlockSumLoop<ValueAt>{f, n, level.data(), s.begin, s.end});
      }
    }
    while (level.size() > 1) {
      std::vector<double> next(sum_block_count(level.size()));
      for (std::size_t b = 0; b < next.size(); ++b) next[b] = sum_block(b, level.size(), BlockSums{level.data()});
      level.swap(next);
    }
    return level[0];
  }

  // *result = sum(n, f), then then(0): the CUDA backend's interface, where
  // the result stays on the device and `then` runs in the sum's launch;
  // `scratch` (sum_scratch_count(n) values) is unused.
  template <class ValueAt, class Then = NothingAfterSum>
  void sum_into(std::size_t n, const ValueAt& f, double* /*scratch*/, double* result, const Then& then = {}) const {
    *result = sum(n, f);
    then(0);
  }

  // A recorded sequence of launches (a CUDA graph there) simply runs here.
  struct Recording {
    void reset() {}
  };
  template <class Body>
  void replay(Recording&, const Body& body) const {
    body();
  }

  // Smallest i in [0, n) with pred(i), or n when there is none.
  template <class Pred>
  std::size_t find_first(std::size_t n, const Pred& pred) const {
    std::size_t first = n;
    if (!uses_threads(n)) {
      run(FirstLoop<Pred>{pred, 0, n, &first});
      return first;
    }
#pragma omp parallel num_threads(threads_) reduction(min : first)
    {
      const Share s = share_of(n);
      std::size_t in_share = s.end;
      run(FirstLoop<Pred>{pred, s.begin, s.end, &in_share});
      if (in_share < s.end) first = in_share;
    }
    return first;
  }

  // Largest f(i) over [0, n); `lowest` when n = 0.
  template <class ValueAt>
  float max(std::size_t n, const ValueAt& f, float lowest) const {
    float m = lowest;
    const std::int64_t count = static_cast<std::int64_t>(n);
#pragma omp parallel for schedule(static) num_threads(threads_) reduction(max : m)
    for (std::int64_t i = 0; i < count; ++i) m = std::max(m, static_cast<float>(f(static_cast<std::size_t>(i))));
    return m;
  }

  // Largest f(i, j, k) over the box nx x ny x nz; `lowest` when it is
  // empty. By rows, so that no cell index is divided per cell.
  template <class ValueAt>
  float max_3d(int nx, int ny, int nz, const ValueAt& f, float lowest) const {
    if (nx <= 0) return lowest;
    return max(static_cast<std::size_t>(ny) * static_cast<std::size_t>(nz), RowMaxAt<ValueAt>{f, nx, ny}, lowest);
  }

  void synchronize() const {}

 private:
  bool uses_threads(std::size_t elements) const { return threads_ > 1 && elements >= kSerialBelow; }

  // The calling OpenMP thread's contiguous share of [0, n), as
  // schedule(static) would split it.
  struct Share {
    std::size_t begin, end;
  };
  static Share share_of(std::size_t n) {
    const std::size_t t = static_cast<std::size_t>(omp_get_thread_num()), count = static_cast<std::size_t>(omp_get_num_threads());
    return Share{n * t / count, n * (t + 1) / count};
  }

  // The calling thread's share of [0, n) by work: thread t starts at the
  // first element with at least t / count of the total work before it.
  template <class W>
  static Share work_share_of(std::size_t n, const W& work_before) {
    const std::size_t t = static_cast<std::size_t>(omp_get_thread_num()), count = static_cast<std::size_t>(omp_get_num_threads());
    const std::size_t total = work_before(n);
    const auto start_of = [&](std::size_t share) {
      if (share == 0) return std::size_t{0};
      if (share == count) return n;
      const std::size_t target = total * share / count;
      std::size_t lo = 0, hi = n;  // the first i with work_before(i) >= target
      while (lo < hi) {
        const std::size_t mid = lo + (hi - lo) / 2;
        if (work_before(mid) < target) lo = mid + 1;
        else hi = mid;
      }
      return lo;
    };
    return Share{start_of(t), start_of(t + 1)};
  }

  // Runs a loop in the copy for this CPU (cpu_isa.h).
  template <class Loop>
  void run(const Loop& loop) const {
#if DP_CPU_HAS_AVX2_COPY
    if (isa_ == CpuIsa::Avx2) {
      run_avx2(loop);
      return;
    }
#endif
    run_local(loop, BaselineCopy{});
  }
#if DP_CPU_HAS_AVX2_COPY
  template <class Loop>
  DP_AVX2_COPY static void run_avx2(const Loop& loop) {
    run_local(loop, Avx2Copy{});
  }
#endif
  // The loop runs from a copy in this frame, whose address nothing else
  // holds: then g++ knows that no store of the loop changes the functor's
  // pointers and scalars. Run through the caller's reference, it reloaded
  // them every element and, in the AVX2 copy, left loops scalar (the CG's
  // vector updates, buoyancy; docs/benchmarks.md).
  template <class Loop, class Copy>
  DP_HOST_INLINE static void run_local(const Loop& loop, Copy copy) {
    const Loop local = loop;
    local(copy);
  }

  int threads_;
  CpuIsa isa_;
};

}  // namespace dp
