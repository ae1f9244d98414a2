#pragma once
// Diffusion of heat and vapor (Alg. 1 line 10), d phi/dt = D lap phi, in
// flux form: each face between two cells that carry air moves
// D dt (phi_lo - phi_hi) / dx^2, computed identically by both cells, so vapor
// is conserved to rounding. Explicit, sub-stepped below the stability bound
// 6 D dt / dx^2 <= 1 (AirGrid chooses the sub-steps): for air's diffusivities
// (~2e-5 m^2/s) and cells of centimetres that bound is seconds, so one
// sub-step is the rule. No flux through walls, rigid or liquid cells, or the
// open faces (heat and vapor exchange with particles is the coupling's,
// paper Sec. 5-6).
#include "air/cell_kind.h"

namespace dp {

template <class T>
struct DiffuseExplicit {
  CellKinds cells;
  const T* in;
  double rate;  // D dt / dx^2
  T* out;

  DP_HD void operator()(int i, int j, int k) const {
    const std::size_t c = cells.grid.cell(i, j, k);
    const std::uint8_t kind = cells.kind[c];
    if (!carries_air(kind)) {
      out[c] = in[c];
      return;
    }
    double sum = 0.0;
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side) {
        int ni, nj, nk;
        if (!cells.neighbour(i, j, k, axis, side, ni, nj, nk)) continue;
        const std::size_t n = cells.grid.cell(ni, nj, nk);
        if (carries_air(cells.kind[n])) sum += static_cast<double>(in[n]) - static_cast<double>(in[c]);
      }
    out[c] = static_cast<T>(static_cast<double>(in[c]) + rate * sum);
  }
};

}  // namespace dp
