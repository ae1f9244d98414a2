#pragma once
// Which instruction set the CPU launcher's loops run in. Each loop is
// compiled twice: for baseline x86-64 (SSE2), which every x86-64 CPU runs,
// and for AVX2, taken where the CPU and the OS support it, so that one
// binary is both portable and fast. The AVX2 copy gets no FMA: a fused
// multiply-add rounds once where the baseline rounds twice, so without it
// every floating-point operation is the baseline's and results agree bit
// for bit (tested; the air fields' fingerprints, docs/benchmarks.md). Only
// the loops and what inlines into them are compiled for AVX2, through a
// function attribute: a whole translation unit compiled so would hand its
// out-of-line template copies to the linker, which may keep the AVX2 copy
// for baseline callers too.
//
// DEWPOINT_CPU_ISA=baseline in the environment keeps every loop on the
// baseline copy (for comparisons; the results are the same).
#include <cstdlib>
#include <cstring>

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__CUDACC__)
#define DP_CPU_HAS_AVX2_COPY 1
#define DP_AVX2_COPY __attribute__((target("avx2")))
#else
#define DP_CPU_HAS_AVX2_COPY 0
#define DP_AVX2_COPY
#endif

namespace dp {

enum class CpuIsa { Baseline, Avx2 };

// Whether this build has the AVX2 copy and this CPU and OS run it.
inline bool cpu_runs_avx2_copy() {
#if DP_CPU_HAS_AVX2_COPY
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") != 0;
#else
  return false;
#endif
}

// The best copy this CPU runs, unless the environment asks for the baseline.
inline CpuIsa detect_cpu_isa() {
  const char* asked = std::getenv("DEWPOINT_CPU_ISA");
  if (asked != nullptr && std::strcmp(asked, "baseline") == 0) return CpuIsa::Baseline;
  return cpu_runs_avx2_copy() ? CpuIsa::Avx2 : CpuIsa::Baseline;
}

inline const char* cpu_isa_name(CpuIsa isa) { return isa == CpuIsa::Avx2 ? "avx2" : "baseline"; }

}  // namespace dp
