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

  // Calls f(n, axis, side) for each unknown neighbour n of cell (i, j, k);
  // returns the diagonal (unknown neighbours plus Dirichlet faces).
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
          f(m, axis, side);
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

// Each cell's stencil bits and diagonal (PoissonLevel::stencil), from the
// unknowns: once per set of unknowns.
struct BuildPoissonStencil {
  PoissonLevel level;
  std::uint8_t* stencil;
  std::uint8_t* diagonal;
  DP_HD void operator()(int i, int j, int k) const {
    const std::size_t c = level.index(i, j, k);
    if (!level.unknown[c]) {
      stencil[c] = 0;
      diagonal[c] = 0;
      return;
    }
    std::uint8_t bits = PoissonLevel::kStencilUnknown;
    const int d = level.for_each_neighbour(
        i, j, k, [&](std::size_t, int axis, int side) { bits |= static_cast<std::uint8_t>(1u << (2 * axis + side)); });
    stencil[c] = bits;
    diagonal[c] = static_cast<std::uint8_t>(d);
  }

#if !defined(__CUDA_ARCH__)
  // Cells 0 .. n - 1 of row (j, k) (CpuExec::parallel_for_3d): whether the
  // rows beside it in y and z exist is decided once; the cells between the
  // row's ends run as one loop of byte operations, which g++ vectorises.
  // The same bytes as cell by cell.
  DP_HOST_INLINE void whole_row(int n, int j, int k) const {
    (*this)(0, j, k);
    if (n > 1) (*this)(n - 1, j, k);
    if (n < 3) return;
    const std::size_t c0 = level.index(0, j, k), row = static_cast<std::size_t>(level.nx), slab = level.slab();
    // A missing neighbour row reads the row itself and is masked off; its
    // domain face counts in the diagonal where it is open.
    const unsigned y_lo = j > 0, y_hi = j + 1 < level.ny, z_lo = k > 0, z_hi = k + 1 < level.nz;
    const unsigned open_faces = (y_lo ? 0u : level.faces.open(1, 0)) + (y_hi ? 0u : level.faces.open(1, 1)) +
                                (z_lo ? 0u : level.faces.open(2, 0)) + (z_hi ? 0u : level.faces.open(2, 1));
    const std::uint8_t* u = level.unknown;
    stencil_row(n, u + c0, u + (y_lo ? c0 - row : c0), u + (y_hi ? c0 + row : c0), u + (z_lo ? c0 - slab : c0),
                u + (z_hi ? c0 + slab : c0), y_lo, y_hi, z_lo, z_hi, open_faces, stencil + c0, diagonal + c0);
  }

  // Cells 1 .. n - 2 of a row `at` with the rows beside it (y_lo .. z_hi:
  // 1 where that row is in the grid). The pointers are restrict parameters:
  // g++ would otherwise test every pair for overlap at run time, more pairs
  // than it allows, and keep the loop scalar.
  DP_HOST_INLINE static void stencil_row(int n, const std::uint8_t* __restrict at, const std::uint8_t* __restrict y_below,
                                         const std::uint8_t* __restrict y_above, const std::uint8_t* __restrict z_below,
                                         const std::uint8_t* __restrict z_above, unsigned y_lo, unsigned y_hi, unsigned z_lo,
                                         unsigned z_hi, unsigned open_faces, std::uint8_t* __restrict out_stencil,
                                         std::uint8_t* __restrict out_diagonal) {
    for (int i = 1; i + 1 < n; ++i) {
      const unsigned x0 = at[i - 1] != 0, x1 = at[i + 1] != 0;
      const unsigned y0 = (y_below[i] != 0) & y_lo, y1 = (y_above[i] != 0) & y_hi;
      const unsigned z0 = (z_below[i] != 0) & z_lo, z1 = (z_above[i] != 0) & z_hi;
      const unsigned self = at[i] != 0;
      const unsigned bits = PoissonLevel::kStencilUnknown | x0 | x1 << 1 | y0 << 2 | y1 << 3 | z0 << 4 | z1 << 5;
      const unsigned d = x0 + x1 + y0 + y1 + z0 + z1 + open_faces;
      out_stencil[i] = static_cast<std::uint8_t>(bits & (0u - self));
      out_diagonal[i] = static_cast<std::uint8_t>(d & (0u - self));
    }
  }
#endif
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
