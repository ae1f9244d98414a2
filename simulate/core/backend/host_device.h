#pragma once
// Marks functions that the CUDA backend calls on the GPU and the CPU backend
// calls on host threads. Physics is written once, with this marker.
#if defined(__CUDACC__)
#define DP_HD __host__ __device__
#else
#define DP_HD
#endif
