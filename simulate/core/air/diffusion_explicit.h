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
    const MacGrid& g = cells.grid;
    const std::size_t c = g.cell(i, j, k);
    // The six neighbours in a fixed order, each a select rather than a
    // branch per neighbour (adding +0 where no flux passes leaves the sum's
    // bits as they are). g++ still does not vectorise it; the pass took a
    // third less time all the same (docs/benchmarks.md).
    const double here = static_cast<double>(in[c]);
    const std::size_t row = static_cast<std::size_t>(g.nx), slab = row * g.ny;
    double sum = 0.0;
    sum += exchange(i > 0, c, c - 1, here);
    sum += exchange(i + 1 < g.nx, c, c + 1, here);
    sum += exchange(j > 0, c, c - row, here);
    sum += exchange(j + 1 < g.ny, c, c + row, here);
    sum += exchange(k > 0, c, c - slab, here);
    sum += exchange(k + 1 < g.nz, c, c + slab, here);
    out[c] = carries_air(cells.kind[c]) ? static_cast<T>(here + rate * sum) : in[c];
  }

 private:
  // phi_n - phi_c where neighbour n lies inside and carries air, else 0;
  // outside, c itself is read in n's place, so every read is in bounds.
  DP_HD_INLINE double exchange(bool inside, std::size_t c, std::size_t n, double here) const {
    const std::size_t at = inside ? n : c;
    return inside && carries_air(cells.kind[at]) ? static_cast<double>(in[at]) - here : 0.0;
  }
};

}  // namespace dp
