#pragma once
// Diffusion of heat and vapor (Alg. 1 line 10), d phi/dt = D lap phi, in
// flux form: each face between two cells that carry air moves
// D dt (phi_lo - phi_hi) / dx^2, computed identically by both cells, so vapor
// is conserved to rounding. Explicit, sub-stepped below the stability bound
// 6 D dt / dx^2 <= 1 (AirGrid chooses the sub-steps): for air's diffusivities
// (~2e-5 m^2/s) and cells of centimetres that bound is seconds, so one
// sub-step is the rule. No flux through walls or rigid or liquid cells (heat
// and vapor exchange with particles is the coupling's, paper Sec. 5-6). An
// open domain face has the ambient value on it (the air outside, as far as
// the grid knows, is the ambient air): a boundary cell exchanges
// 2 D dt (phi_ambient - phi) / dx^2 through it, half a cell being the
// distance, and OpenFaceDiffusion gives the ledger what crossed.
#include "air/cell_kind.h"
#include "air/boundary_faces.h"
#include "math/keep_if.h"

namespace dp {

template <class T>
struct DiffuseExplicit {
  CellKinds cells;
  const T* in;
  double rate;  // D dt / dx^2
  T ambient;    // on the open faces
  T* out;

  DP_HD void operator()(int i, int j, int k) const {
    const MacGrid& g = cells.grid;
    out[g.cell(i, j, k)] = diffused(in, cells.kind, i, j, k, Neighbours{i > 0, i + 1 < g.nx, j > 0, j + 1 < g.ny, k > 0, k + 1 < g.nz});
  }

#if !defined(__CUDA_ARCH__)
  // Cells (0 .. n - 1, j, k), as operator() gives them, for the CPU
  // launcher (CpuExec::parallel_for_3d): which neighbours lie inside is
  // decided once for the row's inner cells, whose loop then has no branch
  // and vectorises. Decided per cell, it kept the loop scalar.
  DP_HOST_INLINE void whole_row(int n, int j, int k) const { diffuse_row(in, cells.kind, out, n, j, k); }
#endif

 private:
#if !defined(__CUDA_ARCH__)
  // The row with the fields as restrict pointers: out is neither of the
  // others, which g++ would otherwise check at run time, one pair of
  // pointers per read, more pairs than it checks before it gives up.
  DP_HOST_INLINE void diffuse_row(const T* __restrict src, const std::uint8_t* __restrict kind, T* __restrict dst, int n,
                                  int j, int k) const {
    const MacGrid& g = cells.grid;
    Neighbours inside{false, n > 1, j > 0, j + 1 < g.ny, k > 0, k + 1 < g.nz};
    const std::size_t first = g.cell(0, j, k);
    dst[first] = diffused(src, kind, 0, j, k, inside);
    inside.x_low = true;
    for (int i = 1; i < n - 1; ++i) dst[first + i] = diffused(src, kind, i, j, k, inside);
    inside.x_high = false;
    if (n > 1) dst[first + n - 1] = diffused(src, kind, n - 1, j, k, inside);
  }
#endif

  // Which of a cell's six neighbours lie inside the grid.
  struct Neighbours {
    bool x_low, x_high, y_low, y_high, z_low, z_high;
  };

  DP_HD_INLINE T diffused(const T* src, const std::uint8_t* kind, int i, int j, int k, const Neighbours& inside) const {
    const MacGrid& g = cells.grid;
    const std::size_t c = g.cell(i, j, k);
    // The six neighbours in a fixed order (adding +0 where no flux passes
    // leaves the sum's bits as they are), every one read and selected
    // without a branch, so that a row of cells vectorises.
    const double here = static_cast<double>(src[c]);
    const std::ptrdiff_t row = g.nx, slab = row * g.ny;
    double sum = 0.0;
    sum += exchange(src, kind, inside.x_low, c, -1, here);
    sum += exchange(src, kind, inside.x_high, c, 1, here);
    sum += exchange(src, kind, inside.y_low, c, -row, here);
    sum += exchange(src, kind, inside.y_high, c, row, here);
    sum += exchange(src, kind, inside.z_low, c, -slab, here);
    sum += exchange(src, kind, inside.z_high, c, slab, here);
    if (cells.faces.any_open()) sum += open_exchange(inside, here);
    return pick_if(carries_air(kind[c]), static_cast<T>(here + rate * sum), src[c]);
  }

  // 2 (phi_ambient - phi_c) for each open domain face of the cell.
  DP_HD_INLINE double open_exchange(const Neighbours& inside, double here) const {
    const DomainFaces& f = cells.faces;
    const int faces = int(!inside.x_low && f.open(0, 0)) + int(!inside.x_high && f.open(0, 1)) + int(!inside.y_low && f.open(1, 0)) +
                      int(!inside.y_high && f.open(1, 1)) + int(!inside.z_low && f.open(2, 0)) + int(!inside.z_high && f.open(2, 1));
    return 2.0 * faces * (static_cast<double>(ambient) - here);
  }

  // phi_n - phi_c where neighbour c + offset lies inside and carries air,
  // else +0; outside, c itself is read in its place, so every read is in
  // bounds.
  DP_HD_INLINE static double exchange(const T* src, const std::uint8_t* kind, bool inside, std::size_t c, std::ptrdiff_t offset,
                                      double here) {
    const std::size_t at = c + (inside ? offset : 0);
    return keep_if(static_cast<double>(src[at]) - here, inside & carries_air(kind[at]));
  }
};

// The vapor that one diffusion sub-step moves through the open domain faces,
// kg: entering (ambient above the boundary cell's) or leaving, as
// DiffuseExplicit moves it, 2 rate (rho_ambient - rho_c) dx^3 per face.
struct OpenFaceDiffusion {
  CellKinds cells;
  const double* vapor;
  double rate;  // D dt / dx^2
  double ambient;
  bool entering;

  DP_HD double operator()(std::size_t b) const {
    const BoundaryFace face = boundary_face(cells.grid, b);
    if (!cells.faces.open(face.axis, face.high ? 1 : 0) || !carries_air(cells.kind[face.cell])) return 0.0;
    const double moved = 2.0 * rate * (ambient - vapor[face.cell]) * static_cast<double>(cells.grid.cell_volume());
    return entering ? (moved > 0 ? moved : 0.0) : (moved < 0 ? -moved : 0.0);
  }
};

}  // namespace dp
