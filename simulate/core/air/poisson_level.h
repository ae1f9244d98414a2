#pragma once
// The pressure Poisson equation on one grid level, in the unscaled form the
// projection solves (pressure_projection.h): for each unknown (air) cell,
//   sum over its faces f of (phi_c - phi_n(f)) = b_c,
// where a face to another unknown cell contributes its phi, a face on an open
// domain face is Dirichlet (phi = 0 outside), and a face to a wall or a
// non-air cell is Neumann (no term). Symmetric, positive (semi)definite:
// singular only when no cell touches an open face.
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "air/cell_kind.h"
#include "air/padded_field.h"
#include "math/keep_if.h"
#include "backend/host_device.h"

namespace dp {

struct PoissonLevel {
  int nx, ny, nz;
  const std::uint8_t* unknown;  // 1 where phi is solved for
  DomainFaces faces;
  // Per cell, found once per solve by BuildPoissonStencil: bit 2 axis + side
  // set where that neighbour is an unknown, kStencilUnknown where the cell
  // is; and the diagonal. May be null before they are built.
  const std::uint8_t* stencil;
  const std::uint8_t* diagonal;
  static constexpr std::uint8_t kStencilUnknown = 0x80;

  DP_HD std::size_t size() const { return static_cast<std::size_t>(nx) * ny * nz; }
  DP_HD std::size_t index(int i, int j, int k) const { return (static_cast<std::size_t>(k) * ny + j) * nx + i; }
  DP_HD void coords(std::size_t c, int& i, int& j, int& k) const {
    i = static_cast<int>(c % nx);
    j = static_cast<int>((c / nx) % ny);
    k = static_cast<int>(c / (static_cast<std::size_t>(nx) * ny));
  }

  // Calls f(n) for each unknown neighbour n of cell (i, j, k); returns the
  // diagonal (unknown neighbours plus Dirichlet faces).
  template <class F>
  DP_HD int for_each_neighbour(int i, int j, int k, const F& f) const {
    int diagonal = 0;
    const int n[3] = {nx, ny, nz};
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side) {
        const int d = side ? 1 : -1;
        const int a = (axis == 0 ? i : (axis == 1 ? j : k)) + d;
        if (a < 0 || a >= n[axis]) {
          if (faces.open(axis, side)) ++diagonal;
          continue;
        }
        const std::size_t m = index(axis == 0 ? a : i, axis == 1 ? a : j, axis == 2 ? a : k);
        if (unknown[m]) {
          ++diagonal;
          f(m);
        }
      }
    return diagonal;
  }

  DP_HD std::size_t slab() const { return static_cast<std::size_t>(nx) * ny; }

  // The diagonal as stored, or 1 where it is 0: a cell with no face to
  // anything has phi = 0 and is given the row of the identity.
  DP_HD_INLINE float diagonal_or_one(std::size_t c) const {
    const unsigned stored = diagonal[c];
    return static_cast<float>(stored > 1u ? stored : 1u);
  }

  // (A x)_c; zero outside the unknowns. x must be a PaddedField's (padding
  // of at least slab()): all six neighbours are loaded and the stencil's
  // bits select them, without a branch.
  DP_HD_INLINE float apply(const float* x, std::size_t c, float* diagonal_out = nullptr) const {
    const unsigned s = stencil[c];
    const std::ptrdiff_t row = nx, slab = row * ny;
    const float* at = x + c;  // neighbours by signed offsets: at c = 0 they lie in the padding
    float off = 0.0f;
    off += keep_if(at[-1], s & 1u);
    off += keep_if(at[1], (s >> 1) & 1u);
    off += keep_if(at[-row], (s >> 2) & 1u);
    off += keep_if(at[row], (s >> 3) & 1u);
    off += keep_if(at[-slab], (s >> 4) & 1u);
    off += keep_if(at[slab], (s >> 5) & 1u);
    const float d = diagonal_or_one(c);
    if (diagonal_out) *diagonal_out = d;
    return keep_if(d * at[0] - off, (s >> 7) & 1u);
  }

  // The same for an x without padding (the caller's first guess): each
  // neighbour is read only where its bit is set.
  DP_HD float apply_unpadded(const float* x, std::size_t c) const {
    const std::uint8_t s = stencil[c];
    if (!(s & kStencilUnknown)) return 0.0f;
    const std::size_t row = static_cast<std::size_t>(nx), slab = row * ny;
    float off = 0.0f;
    if (s & 1u) off += x[c - 1];
    if (s & 2u) off += x[c + 1];
    if (s & 4u) off += x[c - row];
    if (s & 8u) off += x[c + row];
    if (s & 16u) off += x[c - slab];
    if (s & 32u) off += x[c + slab];
    return diagonal_or_one(c) * x[c] - off;
  }
};

struct BuildPoissonStencil {
  PoissonLevel level;
  std::uint8_t* stencil;
  std::uint8_t* diagonal;
  DP_HD void operator()(std::size_t c) const {
    if (!level.unknown[c]) {
      stencil[c] = 0;
      diagonal[c] = 0;
      return;
    }
    int i, j, k;
    level.coords(c, i, j, k);
    std::uint8_t bits = PoissonLevel::kStencilUnknown;
    const std::size_t row = static_cast<std::size_t>(level.nx);
    const int d = level.for_each_neighbour(i, j, k, [&](std::size_t m) {
      const std::size_t delta = m > c ? m - c : c - m;
      const int axis = delta == 1 ? 0 : (delta == row ? 1 : 2);
      bits |= static_cast<std::uint8_t>(1u << (2 * axis + (m > c ? 1 : 0)));
    });
    stencil[c] = bits;
    diagonal[c] = static_cast<std::uint8_t>(d);
  }
};

// r = b - A x for an x without padding (the solve's first residual).
struct PoissonResidual {
  PoissonLevel level;
  const float* x;
  const float* b;
  float* r;
  DP_HD void operator()(std::size_t c) const { r[c] = level.unknown[c] ? b[c] - level.apply_unpadded(x, c) : 0.0f; }
};

// One damped Jacobi sweep, x_out = x + omega D^-1 (b - A x): symmetric, so a
// V-cycle with as many sweeps before as after is a symmetric preconditioner.
struct JacobiSweep {
  PoissonLevel level;
  const float* x;
  const float* b;
  float omega;
  float* out;
  DP_HD_INLINE void operator()(std::size_t c) const {
    float diagonal;
    const float ax = level.apply(x, c, &diagonal);
    out[c] = keep_if(x[c] + omega * (b[c] - ax) / diagonal, level.unknown[c] != 0);
  }
};

// The first sweep from x = 0: x_out = omega D^-1 b, the same values as
// JacobiSweep on a zero x without reading it.
struct JacobiSweepFromZero {
  PoissonLevel level;
  const float* b;
  float omega;
  float* out;
  DP_HD_INLINE void operator()(std::size_t c) const {
    out[c] = keep_if(omega * b[c] / level.diagonal_or_one(c), level.unknown[c] != 0);
  }
};

// `sweeps` damped Jacobi sweeps, alternating between x and tmp so that the
// last pass writes x. From zero, the first pass is JacobiSweepFromZero; from
// a guess in x, sweeps must be even, or the first pass would write the x it
// reads. Either as the passes of one parallel_sweeps call (operator()), or
// pass by pass (from_zero_pass, sweep_pass) as plain per-element kernels
// that the CPU vectorises.
struct JacobiSweeps {
  PoissonLevel level;
  const float* b;
  float omega;
  bool from_zero;
  int sweeps;
  float* x;
  float* tmp;
  DP_HD bool starts_from_zero(int s) const { return s == 0 && from_zero; }
  DP_HD bool writes_x(int s) const { return (sweeps - 1 - s) % 2 == 0; }
  DP_HD JacobiSweepFromZero from_zero_pass(int s) const { return JacobiSweepFromZero{level, b, omega, writes_x(s) ? x : tmp}; }
  DP_HD JacobiSweep sweep_pass(int s) const {
    return JacobiSweep{level, writes_x(s) ? tmp : x, b, omega, writes_x(s) ? x : tmp};
  }
  DP_HD void operator()(int s, std::size_t c) const {
    if (starts_from_zero(s)) from_zero_pass(s)(c);
    else sweep_pass(s)(c);
  }
};

}  // namespace dp
