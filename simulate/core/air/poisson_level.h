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
  // (diagonal 0) has phi = 0: it is given the row of the identity.
  DP_HD float apply(const float* x, std::size_t c, float* diagonal_out = nullptr) const {
    if (!unknown[c]) {
      if (diagonal_out) *diagonal_out = 1.0f;
      return 0.0f;
    }
    int i, j, k;
    coords(c, i, j, k);
    float off = 0.0f;
    const int d = for_each_neighbour(i, j, k, [&](std::size_t m) { off += x[m]; });
    const float diagonal = d > 0 ? static_cast<float>(d) : 1.0f;
    if (diagonal_out) *diagonal_out = diagonal;
    return diagonal * x[c] - off;
  }
};

struct ApplyPoisson {
  PoissonLevel level;
  const float* x;
  float* out;
  DP_HD void operator()(std::size_t c) const { out[c] = level.apply(x, c); }
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

}  // namespace dp
