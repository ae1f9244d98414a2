#pragma once
// CUDA backend: the same interface as CpuExec, running functors in CUDA
// kernels and CCCL Thrust on the GPU. Only .cu files include this header.
#include <cuda_runtime.h>
#include <thrust/copy.h>
#include <thrust/device_vector.h>
#include <thrust/execution_policy.h>
#include <thrust/functional.h>
#include <thrust/iterator/counting_iterator.h>
#include <thrust/iterator/transform_iterator.h>
#include <thrust/reduce.h>
#include <thrust/scan.h>
#include <thrust/sort.h>

#include <cstddef>
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

template <class ValueAt>
struct BlockSum {
  std::size_t n;
  ValueAt f;
  double* out;
  __device__ void operator()(std::size_t b) const { out[b] = sum_block(b, n, f); }
};

template <class Pred>
struct IndexIfTrue {
  std::size_t n;
  Pred pred;
  __device__ std::size_t operator()(std::size_t i) const { return pred(i) ? i : n; }
};

template <class ValueAt>
struct AsFloat {
  ValueAt f;
  __device__ float operator()(std::size_t i) const { return static_cast<float>(f(i)); }
};

struct MinIndex {
  __device__ std::size_t operator()(std::size_t a, std::size_t b) const { return a < b ? a : b; }
};
struct MaxFloat {
  __device__ float operator()(float a, float b) const { return a > b ? a : b; }
};

}  // namespace cuda_detail

class CudaExec {
 public:
  template <class T>
  using Buffer = thrust::device_vector<T>;

  explicit CudaExec(int device = 0) { cuda_detail::check(cudaSetDevice(device), "cudaSetDevice"); }

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
    cuda_detail::for_each_index<<<blocks, kBlock>>>(n, f);
    cuda_detail::check(cudaGetLastError(), "kernel launch");
  }

  // Calls f(i, j, k) for every point of an nx x ny x nz box, one thread per
  // point in a 3-D grid of blocks (x fastest, as CpuExec's rows).
  template <class F>
  void parallel_for_3d(int nx, int ny, int nz, const F& f) const {
    if (nx <= 0 || ny <= 0 || nz <= 0) return;
    const dim3 block(32, 4, 2);
    const dim3 blocks((nx + block.x - 1) / block.x, (ny + block.y - 1) / block.y, (nz + block.z - 1) / block.z);
    cuda_detail::for_each_point<<<blocks, block>>>(nx, ny, nz, f);
    cuda_detail::check(cudaGetLastError(), "kernel launch");
  }

  template <class K, class V>
  void sort_by_key(Buffer<K>& keys, Buffer<V>& values) const {
    thrust::stable_sort_by_key(thrust::cuda::par, keys.begin(), keys.end(), values.begin());
  }

  template <class T>
  void exclusive_scan(const Buffer<T>& in, Buffer<T>& out) const {
    out.resize(in.size());
    thrust::exclusive_scan(thrust::cuda::par, in.begin(), in.end(), out.begin());
  }

  // Same blocked order as CpuExec::sum, so both backends add in one order.
  template <class ValueAt>
  double sum(std::size_t n, const ValueAt& f) const {
    thrust::device_vector<double> partial(sum_block_count(n));
    parallel_for(partial.size(), cuda_detail::BlockSum<ValueAt>{n, f, thrust::raw_pointer_cast(partial.data())});
    std::vector<double> h = download(partial);
    double s = 0.0;
    for (double p : h) s += p;
    return s;
  }

  template <class Pred>
  std::size_t find_first(std::size_t n, const Pred& pred) const {
    auto idx = thrust::make_transform_iterator(thrust::counting_iterator<std::size_t>(0),
                                               cuda_detail::IndexIfTrue<Pred>{n, pred});
    return thrust::reduce(thrust::cuda::par, idx, idx + n, n, cuda_detail::MinIndex{});
  }

  template <class ValueAt>
  float max(std::size_t n, const ValueAt& f, float lowest) const {
    auto v = thrust::make_transform_iterator(thrust::counting_iterator<std::size_t>(0), cuda_detail::AsFloat<ValueAt>{f});
    return thrust::reduce(thrust::cuda::par, v, v + n, lowest, cuda_detail::MaxFloat{});
  }

  void synchronize() const { cuda_detail::check(cudaDeviceSynchronize(), "cudaDeviceSynchronize"); }
};

}  // namespace dp
