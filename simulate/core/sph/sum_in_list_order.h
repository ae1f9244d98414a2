#pragma once
// Sums over one particle's neighbour list in the list's order, with every
// pair's term computed first, in a loop of its own. That loop has no branch
// and nothing carried from pair to pair, so g++ vectorises it: the kernels'
// pieces are selected on their bits and a pair that adds nothing (outside
// the support, i itself) gets a term of +0 by keep_if. The terms are then
// added one at a time in the order the one-loop functor adds them, so the
// sum has the one-loop sum's bits: adding +0 leaves a sum unchanged, since
// a sum that starts at +0 never turns -0 (x + y is -0 only for -0 + -0).
// A subtraction is written as the addition of the negated term, which
// IEEE 754 defines to be the same operation.
//
// In the one-loop form each pair's square roots and divisions wait on the
// branches of its tests and kernel pieces, one pair at a time. On the
// settled glass, PCISPH's density sums (ListedDensity::split_sum) took Ptcl
// from 479 to 376 ms a step, and XSPH, Akinci's surface tension and
// adhesion, and Morris's viscosity between liquid particles 30 %, 50 % and
// 18 % fewer samples (docs/benchmarks.md). Where a loop has little
// arithmetic per pair (the pressure acceleration over the lists' gradient
// factors, the surface normals, heat conduction), the stored terms cost as
// much as they save or more, and those keep their one loop. CPU only, for
// the whole_range hooks (backend/cpu_exec.h): on the GPU a thread takes one
// particle and the functor's one loop.
#include <cstddef>
#include <cstdint>

#include "backend/host_device.h"
#include "math/keep_if.h"
#include "math/vec3.h"

namespace dp {

// Lists up to this long fit the terms' stack arrays; longer ones (never in
// a liquid at rest density) take the functor's one loop.
inline constexpr std::uint32_t kMaxTermsInOrder = 256;

// Whether i's list (a NeighborList) is short enough for the sums below.
template <class List>
DP_HD_INLINE bool fits_in_list_order(const List& list, std::size_t i) {
  return list.offset[i + 1] - list.offset[i] <= kMaxTermsInOrder;
}

// start + term(0) + ... + term(count - 1), added left to right.
template <class Term>
DP_HOST_INLINE float sum_in_list_order(float start, std::uint32_t count, const Term& term) {
  float t[kMaxTermsInOrder];
  for (std::uint32_t k = 0; k < count; ++k) t[k] = term(k);
  float sum = start;
  for (std::uint32_t k = 0; k < count; ++k) sum += t[k];
  return sum;
}

// The same per component, for terms that are vectors.
template <class Term>
DP_HOST_INLINE Vec3 vector_sum_in_list_order(Vec3 start, std::uint32_t count, const Term& term) {
  float tx[kMaxTermsInOrder], ty[kMaxTermsInOrder], tz[kMaxTermsInOrder];
  for (std::uint32_t k = 0; k < count; ++k) {
    const Vec3 v = term(k);
    tx[k] = v.x;
    ty[k] = v.y;
    tz[k] = v.z;
  }
  Vec3 sum = start;
  for (std::uint32_t k = 0; k < count; ++k) {
    sum.x += tx[k];
    sum.y += ty[k];
    sum.z += tz[k];
  }
  return sum;
}

// v where `bit` (0 or 1) is set, +0 in every component where not.
DP_HD_INLINE Vec3 keep_if(Vec3 v, unsigned bit) { return Vec3{keep_if(v.x, bit), keep_if(v.y, bit), keep_if(v.z, bit)}; }

}  // namespace dp
