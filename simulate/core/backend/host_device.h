#pragma once
// Marks functions that the CUDA backend calls on the GPU and the CPU backend
// calls on host threads. Physics is written once, with this marker.
#if defined(__CUDACC__)
#define DP_HD __host__ __device__
#else
#define DP_HD
#endif

// For the few small functions called once per cell in the solvers' hot
// loops, which g++ otherwise keeps out of line: a call per cell cost the
// 64^3 air step a fifth of its time (docs/benchmarks.md).
#if defined(__CUDACC__)
#define DP_HD_INLINE __host__ __device__ __forceinline__
#else
#define DP_HD_INLINE __attribute__((always_inline)) inline
#endif

// Asks the cache for *p ahead of its use, where a kernel reads through a
// permutation the hardware prefetcher cannot follow. Nothing on the GPU,
// whose threads hide memory latency by their number.
namespace dp {
DP_HD_INLINE void prefetch(const void* p) {
#if !defined(__CUDA_ARCH__)
  __builtin_prefetch(p);
#else
  (void)p;
#endif
}
}  // namespace dp

// The same for host-only functions the CPU launcher calls per group of
// points (four_along_x): inlined into its loops, they are compiled with
// each loop's instruction set (cpu_isa.h) instead of the baseline's alone.
#define DP_HOST_INLINE __attribute__((always_inline)) inline

// Before a DP_HD template that calls the methods of an executor it is
// given: the launchers' are host functions, a GPU thread block's
// (BlockExec) device functions, and each instantiation is only ever called
// where its executor's run; nvcc would otherwise warn of every host call.
#if defined(__CUDACC__)
#define DP_EXEC_TEMPLATE _Pragma("nv_exec_check_disable")
#else
#define DP_EXEC_TEMPLATE
#endif
