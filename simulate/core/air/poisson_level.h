#pragma once
// The pressure Poisson equation on one grid level, in the unscaled form the
// projection solves (pressure_projection.h): for each unknown (air) cell,
//   sum over its faces f of (phi_c - phi_n(f)) = b_c,
// where a face to another unknown cell contributes its phi, a face on an open
// domain face is Dirichlet (phi = 0 outside), and a face to a wall or a
// non-air cell is Neumann (no term). Symmetric, positive (semi)definite:
// singular only when no cell touches an open face.
#include <cstdint>

#include "air/cell_kind.h"
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

  // (A x)_c; zero outside the unknowns. A cell with no face to anything
  // (diagonal 0) has phi = 0: it is given the row of the identity. Reads the
  // stencil, so each neighbour costs a bit test instead of bounds checks.
  DP_HD_INLINE float apply(const float* x, std::size_t c, float* diagonal_out = nullptr) const {
    const std::uint8_t s = stencil[c];
    if (!(s & kStencilUnknown)) {
      if (diagonal_out) *diagonal_out = 1.0f;
      return 0.0f;
    }
    const std::size_t row = static_cast<std::size_t>(nx), slab = row * ny;
    float off = 0.0f;
    if (s & 1u) off += x[c - 1];
    if (s & 2u) off += x[c + 1];
    if (s & 4u) off += x[c - row];
    if (s & 8u) off += x[c + row];
    if (s & 16u) off += x[c - slab];
    if (s & 32u) off += x[c + slab];
    const float d = diagonal[c] ? static_cast<float>(diagonal[c]) : 1.0f;
    if (diagonal_out) *diagonal_out = d;
    return d * x[c] - off;
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

struct PoissonResidual {
  PoissonLevel level;
  const float* x;
  const float* b;
  float* r;
  DP_HD void operator()(std::size_t c) const { r[c] = level.unknown[c] ? b[c] - level.apply(x, c) : 0.0f; }
};

// One damped Jacobi sweep, x_out = x + omega D^-1 (b - A x): symmetric, so a
// V-cycle with as many sweeps before as after is a symmetric preconditioner.
struct JacobiSweep {
  PoissonLevel level;
  const float* x;
  const float* b;
  float omega;
  float* out;
  DP_HD void operator()(std::size_t c) const {
    if (!level.unknown[c]) {
      out[c] = 0.0f;
      return;
    }
    float diagonal;
    const float ax = level.apply(x, c, &diagonal);
    out[c] = x[c] + omega * (b[c] - ax) / diagonal;
  }
};

// The first sweep from x = 0: x_out = omega D^-1 b, the same values as
// JacobiSweep on a zero x without reading it.
struct JacobiSweepFromZero {
  PoissonLevel level;
  const float* b;
  float omega;
  float* out;
  DP_HD void operator()(std::size_t c) const {
    if (!level.unknown[c]) {
      out[c] = 0.0f;
      return;
    }
    const float diagonal = level.diagonal[c] ? static_cast<float>(level.diagonal[c]) : 1.0f;
    out[c] = omega * b[c] / diagonal;
  }
};

// `sweeps` damped Jacobi sweeps as the passes of one parallel_sweeps call,
// alternating between x and tmp so that the last pass writes x. From zero,
// the first pass is JacobiSweepFromZero; from a guess in x, sweeps must be
// even, or the first pass would write the x it reads.
struct JacobiSweeps {
  PoissonLevel level;
  const float* b;
  float omega;
  bool from_zero;
  int sweeps;
  float* x;
  float* tmp;
  DP_HD void operator()(int s, std::size_t c) const {
    const bool writes_x = (sweeps - 1 - s) % 2 == 0;
    float* out = writes_x ? x : tmp;
    if (s == 0 && from_zero) JacobiSweepFromZero{level, b, omega, out}(c);
    else JacobiSweep{level, writes_x ? tmp : x, b, omega, out}(c);
  }
};

}  // namespace dp
