#pragma once
// Pressure projection (paper Eq. 1, Alg. 1 line 11; Stam 1999, with the
// staggered grid of Fedkiw et al. 2001). With phi = p dt / rho_air, each free
// face loses the pressure gradient, u_f -= (phi_hi - phi_lo) / dx, which
// makes the discrete divergence of every air cell zero when
//   sum over its faces of (phi_c - phi_n) = -dx * sum over its faces of u.n,
// the Poisson equation of poisson_level.h. Open domain faces hold phi = 0
// (ambient pressure), walls and non-air cells are Neumann.
#include "air/boundary_conditions.h"
#include "air/poisson_level.h"

namespace dp {

struct MarkAirUnknowns {
  const std::uint8_t* kind;
  std::uint8_t* unknown;
  DP_HD void operator()(std::size_t c) const { unknown[c] = kind[c] == kAirCell ? 1 : 0; }
};

// Net outflow of cell c, sum over its faces of u.n (m/s): dx times the
// discrete divergence.
DP_HD inline float net_outflow(const MacGrid& g, const float* u, const float* v, const float* w, int i, int j, int k) {
  return (u[g.face(0, i + 1, j, k)] - u[g.face(0, i, j, k)]) + (v[g.face(1, i, j + 1, k)] - v[g.face(1, i, j, k)]) +
         (w[g.face(2, i, j, k + 1)] - w[g.face(2, i, j, k)]);
}

struct ComputeProjectionRhs {
  CellKinds cells;
  const float* u;
  const float* v;
  const float* w;
  float* b;
  DP_HD void operator()(int i, int j, int k) const {
    const std::size_t c = cells.grid.cell(i, j, k);
    if (cells.kind[c] != kAirCell) {
      b[c] = 0.0f;
      return;
    }
    b[c] = -cells.grid.dx * net_outflow(cells.grid, u, v, w, i, j, k);
  }
};

// The faces of axis Axis.
template <int Axis>
struct SubtractPressureGradient {
  static constexpr int axis = Axis;
  CellKinds cells;
  const float* phi;
  float* u;
  DP_HD void operator()(int i, int j, int k) const {
    subtract(cells.grid.face(axis, i, j, k), face_sides(cells.grid, axis, i, j, k));
  }

  DP_HD void subtract(std::size_t f, const FaceSides& s) const {
    if (!face_is_free(cells, axis, s)) return;
    const float hi = s.hi ? phi[s.cell_hi] : 0.0f;
    const float lo = s.lo ? phi[s.cell_lo] : 0.0f;
    u[f] -= (hi - lo) / cells.grid.dx;
  }
};

}  // namespace dp
