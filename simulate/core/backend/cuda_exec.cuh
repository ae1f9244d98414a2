#pragma once
// CUDA backend: the same interface as CpuExec, running functors in CUDA
// kernels and CCCL Thrust on the GPU. Only .cu files include this header.
#include <cuda_runtime.h>
#include <thrust/copy.h>
#include <thrust/device_vector.h>
#include <thrust/execution_policy.h>
#include <thrust/scan.h>
#include <thrust/sort.h>

#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "backend/blocked_sum.h"

namespace dp {

namespace cuda_detail {

inline void check(cudaError_t err, const char* what) {
  if (err != cudaSuccess) throw std::runtime_error(std::string("CUDA error in ") + what + ": " + cudaGetErrorString(err));
}

template <class F>
__global__ void for_each_index(std::size_t n, F f) {
  std::size_t i = static_cast<std::size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (i < n) f(i);
}

template <class F>
__global__ void for_each_point(int nx, int ny, int nz, F f) {
  const int i = static_cast<int>(blockIdx.x * blockDim.x + threadIdx.x);
  const int j = static_cast<int>(blockIdx.y * blockDim.y + threadIdx.y);
  const int k = static_cast<int>(blockIdx.z * blockDim.z + threadIdx.z);
  if (i < nx && j < ny && k < nz) f(i, j, k);
}

constexpr unsigned kWholeWarp = 0xffffffffu;

// The lanes' values folded as a tree, lane l taking lane l + 16, then
// l + 8, ... (blocked_sum.h); lane 0 holds the result.
template <class T, class Combine>
__device__ T fold_lanes(T v, const Combine& combine) {
  for (unsigned offset = kSumLanes / 2; offset > 0; offset /= 2) v = combine(v, __shfl_down_sync(kWholeWarp, v, offset));
  return v;
}

// Threads of a thread block that reduces one block of kSumBlock elements:
// four terms per thread.
constexpr unsigned kSumThreads = 256;

// Block `block` of [0, n) reduced by the thread block, in blocked_sum.h's
// order; every thread of the block calls it, and thread 0 gets the result.
// Each thread takes its terms, term_at(i), contiguous across the threads,
// so the block's loads are all in flight at once (a warp walking 32 terms
// per lane one after another was latency-bound); they meet in `term`
// (shared), and the first warp combines them as blocked_sum.h's lanes do
// (lane l: terms l, l + 32, ... in order, from `identity`), then folds the
// lanes.
template <class T, class TermAt, class Combine>
__device__ T reduce_block_by_threads(std::size_t block, std::size_t n, const TermAt& term_at, T identity,
                                     const Combine& combine, T* term) {
  const std::size_t begin = block * kSumBlock;
  const unsigned count = static_cast<unsigned>(n - begin < kSumBlock ? n - begin : kSumBlock);
  for (unsigned t = threadIdx.x; t < count; t += kSumThreads) term[t] = term_at(begin + t);
  __syncthreads();
  T v = identity;
  if (threadIdx.x < kSumLanes) {
    for (unsigned t = threadIdx.x; t < count; t += kSumLanes) v = combine(v, term[t]);
    v = fold_lanes(v, combine);
  }
  return v;
}

// Sums: f(i) as a double, added from 0.
template <class ValueAt>
struct AsDouble {
  ValueAt f;
  __device__ double operator()(std::size_t i) const { return static_cast<double>(f(i)); }
};
struct Add {
  __device__ double operator()(double a, double b) const { return a + b; }
};
// Maxima: f(i) as a float, taken from the lowest value.
template <class ValueAt>
struct AsFloat {
  ValueAt f;
  __device__ float operator()(std::size_t i) const { return static_cast<float>(f(i)); }
};
struct Max {
  __device__ float operator()(float a, float b) const { return fmaxf(a, b); }
};
// First index: i where pred(i) holds, n elsewhere, the least taken from n.
template <class Pred>
struct IndexWhere {
  Pred pred;
  std::size_t n;
  __device__ unsigned long long operator()(std::size_t i) const { return pred(i) ? i : n; }
};
struct Min {
  __device__ unsigned long long operator()(unsigned long long a, unsigned long long b) const { return a < b ? a : b; }
};
// f(i, j, k) at cell index c = i + nx (j + ny k) of a box nx x ny.
template <class F>
struct AtCell {
  F f;
  int nx, ny;
  __device__ float operator()(std::size_t c) const {
    const std::size_t row = c / static_cast<std::size_t>(nx);
    return f(static_cast<int>(c % static_cast<std::size_t>(nx)), static_cast<int>(row % static_cast<std::size_t>(ny)),
             static_cast<int>(row / static_cast<std::size_t>(ny)));
  }
};

// out[b] = block b's value, one thread block per block.
template <class T, class TermAt, class Combine>
__global__ void __launch_bounds__(kSumThreads) reduce_each_block(std::size_t n, TermAt term_at, T identity, Combine combine, T* out) {
  __shared__ T term[kSumBlock];
  const T v = reduce_block_by_threads(blockIdx.x, n, term_at, identity, combine, term);
  if (threadIdx.x == 0) out[blockIdx.x] = v;
}

// Block sums written by other thread blocks of the same launch, read from
// L2 (the point of coherence) rather than from a possibly stale L1 line.
struct CoherentBlockSums {
  const double* sums;
  __device__ double operator()(std::size_t i) const { return __ldcg(sums + i); }
};

// A whole sum in one launch, one thread block per block of kSumBlock
// elements. Each thread block writes its block's sum to level_sums; the one
// that finishes last (counted in *blocks_done, which it sets back to 0 for
// the next sum) then adds the levels of block sums by itself, block by
// block in the order that a launch per level would, writes *result and
// calls then(0). So the result has the same bits as CpuExec::sum, and the
// levels after the first cost no launches.
template <class ValueAt, class Then>
__global__ void __launch_bounds__(kSumThreads) sum_in_one_launch(std::size_t n, ValueAt f, unsigned long long* blocks_done,
                                                                 double* level_sums, double* result, Then then) {
  __shared__ double term[kSumBlock];
  __shared__ bool last;
  const unsigned blocks = gridDim.x;
  const double v = reduce_block_by_threads(blockIdx.x, n, AsDouble<ValueAt>{f}, 0.0, Add{}, term);
  if (blocks == 1) {
    if (threadIdx.x == 0) {
      *result = v;
      then(0);
    }
    return;
  }
  if (threadIdx.x == 0) {
    level_sums[blockIdx.x] = v;
    __threadfence();  // the block's sum is visible before the count says so
    last = atomicAdd(blocks_done, 1ull) == blocks - 1;
  }
  __syncthreads();
  if (!last) return;  // the same for every thread of the block
  __threadfence();    // and this block sees every other block's sum
  const double* level = level_sums;
  double* out = level_sums + blocks;
  for (std::size_t count = blocks;;) {
    const std::size_t next = sum_block_count(count);
    for (std::size_t b = 0; b < next; ++b) {
      __syncthreads();  // the first warp is done with `term`
      const double s = reduce_block_by_threads(b, count, CoherentBlockSums{level}, 0.0, Add{}, term);
      if (threadIdx.x == 0) (next == 1 ? *result : out[b]) = s;
    }
    if (next == 1) break;
    __threadfence();
    __syncthreads();  // thread 0's sums, before any thread reads them as the next level
    level = out;
    out += next;
    count = next;
  }
  if (threadIdx.x == 0) {
    then(0);
    *blocks_done = 0;
  }
}

// One pass of a parallel_sweeps call: f(sweep, i) as a per-element functor.
template <class F>
struct SweepOf {
  F f;
  int sweep;
  __device__ void operator()(std::size_t i) const { f(sweep, i); }
};

}  // namespace cuda_detail

// The launcher interface inside one thread block (CudaExec::in_one_block):
// every thread of the block calls each method with the same arguments, the
// threads share the pass's elements, and a barrier ends each pass, so that
// the next one sees everything this one wrote. For chains of passes over a
// few thousand elements, which cost a launch each as kernels.
struct BlockExec {
  template <class F>
  __device__ void parallel_for(std::size_t n, const F& f) const {
    for (std::size_t i = threadIdx.x; i < n; i += blockDim.x) f(i);
    __syncthreads();
  }
  template <class F>
  __device__ void parallel_for_3d(int nx, int ny, int nz, const F& f) const {
    const unsigned n = static_cast<unsigned>(nx) * static_cast<unsigned>(ny) * static_cast<unsigned>(nz);
    for (unsigned p = threadIdx.x; p < n; p += blockDim.x) {
      const unsigned row = p / static_cast<unsigned>(nx);
      f(static_cast<int>(p - row * static_cast<unsigned>(nx)), static_cast<int>(row % static_cast<unsigned>(ny)),
        static_cast<int>(row / static_cast<unsigned>(ny)));
    }
    __syncthreads();
  }
  template <class F>
  __device__ void parallel_sweeps(std::size_t n, int sweeps, const F& f) const {
    for (int s = 0; s < sweeps; ++s) parallel_for(n, cuda_detail::SweepOf<F>{f, s});
  }
};

namespace cuda_detail {

constexpr unsigned kOneBlockThreads = 1024;

template <class Body>
__global__ void __launch_bounds__(kOneBlockThreads) in_one_block(Body body) {
  body(BlockExec{});
}

// Runs `sweeps` dependent passes of f(sweep, i) over [0, n) in one thread
// block, with a barrier between passes (n at most one block's threads).
template <class F>
__global__ void sweeps_in_one_block(std::size_t n, int sweeps, F f) {
  BlockExec{}.parallel_sweeps(n, sweeps, f);
}

class Stream {
 public:
  Stream() { check(cudaStreamCreate(&stream_), "cudaStreamCreate"); }
  Stream(const Stream&) = delete;
  Stream& operator=(const Stream&) = delete;
  ~Stream() { cudaStreamDestroy(stream_); }
  cudaStream_t get() const { return stream_; }

 private:
  cudaStream_t stream_ = nullptr;
};

// Device and pinned host memory for the per-block results of reductions,
// kept between calls: allocating per call cost more than the reduction.
class ReductionScratch {
 public:
  ReductionScratch() = default;
  ReductionScratch(const ReductionScratch&) = delete;
  ReductionScratch& operator=(const ReductionScratch&) = delete;
  ~ReductionScratch() {
    cudaFree(device_);
    cudaFreeHost(host_);
  }
  void reserve(std::size_t bytes) {
    if (bytes <= bytes_) return;
    cudaFree(device_);
    cudaFreeHost(host_);
    device_ = host_ = nullptr;
    bytes_ = 0;
    check(cudaMalloc(&device_, bytes), "cudaMalloc (reduction scratch)");
    check(cudaMallocHost(&host_, bytes), "cudaMallocHost (reduction scratch)");
    bytes_ = bytes;
  }
  void* device() const { return device_; }
  void* host() const { return host_; }

 private:
  void* device_ = nullptr;
  void* host_ = nullptr;
  std::size_t bytes_ = 0;
};

}  // namespace cuda_detail

class CudaExec {
 public:
  template <class T>
  using Buffer = thrust::device_vector<T>;

  // Convergence checks of iterative solvers are host round trips: with
  // nothing else to go by, one every this many iterations, which run
  // between checks as recorded graphs (PoissonPcg checks first where its
  // last solve ended).
  static constexpr int kIterationsPerCheck = 4;

  // No: a sum runs one warp per 1024 elements, so a fused stencil pass
  // would run on a thirty-second of the threads a pass of its own gets.
  static constexpr bool kFusesPassesIntoSums = false;

  // Buffers are device memory: reading one element on the host is a copy
  // and a wait for the stream.
  static constexpr bool kBuffersInHostMemory = false;

  // Each pass is a launch, a few microseconds however small the pass: fewer
  // passes over the same terms beat separable ones (CycleLayout).
  static constexpr bool kPassCostsALaunch = true;

  // Chains of passes over at most this many elements run in one thread
  // block (in_one_block): four per thread, a barrier between passes instead
  // of a launch.
  static constexpr std::size_t kOneBlockElements = 4 * cuda_detail::kOneBlockThreads;

  explicit CudaExec(int device = 0) {
    cuda_detail::check(cudaSetDevice(device), "cudaSetDevice");
    stream_ = std::make_shared<cuda_detail::Stream>();
  }

  // Every kernel of this backend runs on this stream: a blocking stream, so
  // it stays ordered with Thrust's vector operations on the default stream,
  // and one that can be captured into a CUDA graph (the default stream
  // cannot).
  cudaStream_t stream() const { return stream_->get(); }

  static constexpr const char* name() { return "cuda"; }

  template <class T>
  static T* ptr(Buffer<T>& b) { return thrust::raw_pointer_cast(b.data()); }
  template <class T>
  static const T* ptr(const Buffer<T>& b) { return thrust::raw_pointer_cast(b.data()); }
  template <class T>
  static void upload(Buffer<T>& dst, const std::vector<T>& src) { dst.assign(src.begin(), src.end()); }
  template <class T>
  static T download_one(const Buffer<T>& src, std::size_t i) { return src[i]; }  // one element copied back
  template <class T>
  static std::vector<T> download(const Buffer<T>& src) {
    std::vector<T> h(src.size());
    thrust::copy(src.begin(), src.end(), h.begin());
    return h;
  }

  template <class F>
  void parallel_for(std::size_t n, const F& f) const {
    if (n == 0) return;
    constexpr unsigned kBlock = 256;
    unsigned blocks = static_cast<unsigned>((n + kBlock - 1) / kBlock);
    cuda_detail::for_each_index<<<blocks, kBlock, 0, stream()>>>(n, f);
    cuda_detail::check(cudaGetLastError(), "kernel launch");
  }

  // CpuExec balances its threads' shares by work; here each element has its
  // own thread anyway.
  template <class W, class F>
  void parallel_for_by_work(std::size_t n, const W&, const F& f) const {
    parallel_for(n, f);
  }

  // Calls f(i, j, k) for every point of an nx x ny x nz box, one thread per
  // point in a 3-D grid of blocks (x fastest, as CpuExec's rows).
  template <class F>
  void parallel_for_3d(int nx, int ny, int nz, const F& f) const {
    if (nx <= 0 || ny <= 0 || nz <= 0) return;
    const dim3 block(32, 4, 2);
    const dim3 blocks((nx + block.x - 1) / block.x, (ny + block.y - 1) / block.y, (nz + block.z - 1) / block.z);
    cuda_detail::for_each_point<<<blocks, block, 0, stream()>>>(nx, ny, nz, f);
    cuda_detail::check(cudaGetLastError(), "kernel launch");
  }

  template <class K, class V>
  void sort_by_key(Buffer<K>& keys, Buffer<V>& values) const {
    thrust::stable_sort_by_key(thrust::cuda::par.on(stream()), keys.begin(), keys.end(), values.begin());
  }

  template <class T>
  void exclusive_scan(const Buffer<T>& in, Buffer<T>& out) const {
    out.resize(in.size());
    thrust::exclusive_scan(thrust::cuda::par.on(stream()), in.begin(), in.end(), out.begin());
  }

  // Same order as CpuExec::sum (blocked_sum.h), so both backends add alike;
  // f is called once per element, as there, so it may write element i.
  template <class ValueAt>
  double sum(std::size_t n, const ValueAt& f) const {
    scratch_->reserve((sum_scratch_count(n) + 1) * sizeof(double));
    double* device = static_cast<double*>(scratch_->device());
    // The count of finished blocks: zero, whatever max or find_first left there.
    cuda_detail::check(cudaMemsetAsync(device + 1, 0, sizeof(double), stream()), "cudaMemsetAsync (sum)");
    sum_into(n, f, device + 1, device);
    cuda_detail::check(cudaMemcpyAsync(scratch_->host(), device, sizeof(double), cudaMemcpyDeviceToHost, stream()),
                       "cudaMemcpyAsync (sum)");
    cuda_detail::check(cudaStreamSynchronize(stream()), "cudaStreamSynchronize (sum)");
    return *static_cast<const double*>(scratch_->host());
  }

  // *result = sum(n, f), left on the device: no host round trip, so it can
  // be part of a recorded graph. `scratch` holds sum_scratch_count(n)
  // values, zero-filled before its first sum: the count of finished blocks
  // (as the bits of an integer), then the levels of block sums. Then
  // then(0) runs once, after *result is written, as a parallel_for(1, then)
  // after the sum would, without a launch of its own. One launch in all.
  template <class ValueAt, class Then = NothingAfterSum>
  void sum_into(std::size_t n, const ValueAt& f, double* scratch, double* result, const Then& then = {}) const {
    static_assert(sizeof(unsigned long long) == sizeof(double), "the count takes one value's room");
    const unsigned blocks = n > 0 ? static_cast<unsigned>(sum_block_count(n)) : 1u;  // n = 0: one empty block gives 0
    cuda_detail::sum_in_one_launch<<<blocks, cuda_detail::kSumThreads, 0, stream()>>>(
        n, f, reinterpret_cast<unsigned long long*>(scratch), scratch + 1, result, then);
    cuda_detail::check(cudaGetLastError(), "kernel launch");
  }

  // A sequence of launches recorded once as a CUDA graph and replayed:
  // one launch for the whole sequence. The sequence must launch the same
  // kernels on the same buffers every time (reset() when they change) and
  // must not wait for the device.
  class Recording {
   public:
    Recording() = default;
    Recording(const Recording&) = delete;
    Recording& operator=(const Recording&) = delete;
    ~Recording() { reset(); }
    void reset() {
      if (graph_) cudaGraphExecDestroy(graph_);
      graph_ = nullptr;
    }

   private:
    friend class CudaExec;
    cudaGraphExec_t graph_ = nullptr;
  };

  template <class Body>
  void replay(Recording& recording, const Body& body) const {
    if (!recording.graph_) {
      cudaGraph_t graph = nullptr;
      cuda_detail::check(cudaStreamBeginCapture(stream(), cudaStreamCaptureModeThreadLocal), "cudaStreamBeginCapture");
      body();
      cuda_detail::check(cudaStreamEndCapture(stream(), &graph), "cudaStreamEndCapture");
      const cudaError_t made = cudaGraphInstantiate(&recording.graph_, graph, 0);
      cudaGraphDestroy(graph);
      cuda_detail::check(made, "cudaGraphInstantiate");
    }
    cuda_detail::check(cudaGraphLaunch(recording.graph_, stream()), "cudaGraphLaunch");
  }

  // Smallest i in [0, n) with pred(i), or n when there is none.
  template <class Pred>
  std::size_t find_first(std::size_t n, const Pred& pred) const {
    const std::size_t blocks = sum_block_count(n);
    const unsigned long long* first = reduce_blocks(n, cuda_detail::IndexWhere<Pred>{pred, n}, static_cast<unsigned long long>(n),
                                                    cuda_detail::Min{});
    std::size_t m = n;
    for (std::size_t b = 0; b < blocks; ++b) m = first[b] < m ? static_cast<std::size_t>(first[b]) : m;
    return m;
  }

  // Largest f(i) over [0, n); `lowest` when n = 0.
  template <class ValueAt>
  float max(std::size_t n, const ValueAt& f, float lowest) const {
    const std::size_t blocks = sum_block_count(n);
    const float* block_max = reduce_blocks(n, cuda_detail::AsFloat<ValueAt>{f}, lowest, cuda_detail::Max{});
    float m = lowest;
    for (std::size_t b = 0; b < blocks; ++b) m = block_max[b] > m ? block_max[b] : m;
    return m;
  }

  // Largest f(i, j, k) over the box nx x ny x nz; `lowest` when it is
  // empty. By cells: neighbouring lanes read neighbouring cells.
  template <class ValueAt>
  float max_3d(int nx, int ny, int nz, const ValueAt& f, float lowest) const {
    if (nx <= 0 || ny <= 0 || nz <= 0) return lowest;
    const std::size_t n = static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny) * static_cast<std::size_t>(nz);
    return max(n, cuda_detail::AtCell<ValueAt>{f, nx, ny}, lowest);
  }

  // body(BlockExec{}) in one thread block of kOneBlockThreads: one launch
  // for a whole chain of small passes.
  template <class Body>
  void in_one_block(const Body& body) const {
    cuda_detail::in_one_block<<<1, cuda_detail::kOneBlockThreads, 0, stream()>>>(body);
    cuda_detail::check(cudaGetLastError(), "kernel launch");
  }

  // Calls f(s, i) for s = 0 .. sweeps-1 and every i in [0, n), all of pass
  // s before any of pass s + 1. A small n runs in one thread block with
  // barriers between passes: one launch instead of one per pass.
  template <class F>
  void parallel_sweeps(std::size_t n, int sweeps, const F& f) const {
    if (n == 0 || sweeps <= 0) return;
    if (n <= kOneBlockSweeps) {
      const unsigned threads = static_cast<unsigned>((n + 31) / 32 * 32);
      cuda_detail::sweeps_in_one_block<<<1, threads, 0, stream()>>>(n, sweeps, f);
      cuda_detail::check(cudaGetLastError(), "kernel launch");
      return;
    }
    for (int s = 0; s < sweeps; ++s) parallel_for(n, cuda_detail::SweepOf<F>{f, s});
  }

  void synchronize() const { cuda_detail::check(cudaDeviceSynchronize(), "cudaDeviceSynchronize"); }

 private:
  static constexpr std::size_t kOneBlockSweeps = 1024;

  // Reduces each block of [0, n) (one thread block per block), copies the
  // per-block results to pinned host memory and waits for them; returns
  // the host copy (valid until the next reduction).
  template <class T, class TermAt, class Combine>
  const T* reduce_blocks(std::size_t n, const TermAt& term_at, T identity, const Combine& combine) const {
    const std::size_t blocks = sum_block_count(n);
    if (blocks == 0) return nullptr;
    scratch_->reserve(blocks * sizeof(T));
    T* device = static_cast<T*>(scratch_->device());
    cuda_detail::reduce_each_block<<<static_cast<unsigned>(blocks), cuda_detail::kSumThreads, 0, stream()>>>(n, term_at, identity,
                                                                                                         combine, device);
    cuda_detail::check(cudaGetLastError(), "kernel launch");
    cuda_detail::check(cudaMemcpyAsync(scratch_->host(), device, blocks * sizeof(T), cudaMemcpyDeviceToHost, stream()),
                       "cudaMemcpyAsync (reduction)");
    cuda_detail::check(cudaStreamSynchronize(stream()), "cudaStreamSynchronize (reduction)");
    return static_cast<const T*>(scratch_->host());
  }

  std::shared_ptr<cuda_detail::Stream> stream_;
  std::shared_ptr<cuda_detail::ReductionScratch> scratch_ = std::make_shared<cuda_detail::ReductionScratch>();
};

}  // namespace dp
