#pragma once
// Conservative (flux-form, finite-volume) vapor advection; the paper's
// semi-Lagrangian transport (Eq. 4) does not conserve mass, and its
// mass-preserving cycle needs a transport that does (docs/paper-map.md,
// departures). Each face carries one flux, computed identically by the two
// cells it separates, so what one loses the other gains and the sum over a
// closed box changes only by rounding. Face values are MUSCL with a minmod
// limited slope (van Leer 1979) and the Lax-Wendroff factor (1 - |c|), which
// keeps the scheme second order in smooth regions and positive while each
// cell's outflow Courant number stays below 2/3 (CellOutflowSpeed; AirGrid
// sub-steps to stay there).
#include <cstdint>

#include "air/boundary_conditions.h"
#include "air/boundary_faces.h"
#include "air/cell_kind.h"
#include "math/keep_if.h"

namespace dp {

// Both comparisons are made whatever the first one says: g++ moves no
// floating-point operation (which may trap) out from under a condition, so
// a conditional one keeps a branch in the loop and the loop scalar.
DP_HD_INLINE double minmod(double a, double b) {
  const bool opposite = a * b <= 0.0, a_smaller = fabs(a) < fabs(b);
  return opposite ? 0.0 : (a_smaller ? a : b);
}

// The change of vapor density (kg/m^3) a face moves from its low to its high
// cell in one sub-step of length dt: c rho_face, c = u dt / dx. Faces next to
// rigid or liquid cells and closed walls carry nothing; open faces let the
// cell's vapor out and the ambient vapor in.
struct VaporFaceFlux {
  CellKinds cells;
  const double* vapor;
  double ambient_vapor;
  float dt;

  // Face (i, j, k) of axis Axis; a compile-time axis folds the index
  // arithmetic and the axis selects of every face.
  template <int Axis>
  DP_HD_INLINE double along(const float* u, int i, int j, int k) const {
    const MacGrid& g = cells.grid;
    const FaceSides s = face_sides(g, Axis, i, j, k);
    const double c = courant(u, g.face(Axis, i, j, k));
    if (!(s.lo && s.hi)) return on_domain_face(Axis, s, c);
    const int a = Axis == 0 ? i : (Axis == 1 ? j : k);
    return between_cells<Axis>(i, j, k, c, a >= 2, a + 1 < g.n(Axis));
  }

#if !defined(__CUDA_ARCH__)
  // The faces (0 .. n - 1, j, k) of axis Axis into out, as along() gives
  // them, for the CPU launcher (CpuExec::parallel_for_3d): whether a face
  // lies on the domain and which of its neighbours lie inside is decided
  // once for the row's inner faces, whose loop then has no branch and
  // vectorises. Decided per face, it kept the loop scalar.
  template <int Axis>
  DP_HOST_INLINE void row(const float* u, double* out, int n, int j, int k) const {
    const MacGrid& g = cells.grid;
    const std::size_t first = g.face(Axis, 0, j, k);
    int inner_begin = 0, inner_end = n;
    bool below_inside = true, above_inside = true;
    if constexpr (Axis == 0) {  // faces 0, 1, nx - 1 and nx are not inner ones
      inner_begin = n < 2 ? n : 2;
      inner_end = n - 2 > inner_begin ? n - 2 : inner_begin;
    } else {
      const int a = Axis == 1 ? j : k;
      if (a == 0 || a == g.n(Axis)) inner_end = 0;
      below_inside = a >= 2;
      above_inside = a + 1 < g.n(Axis);
    }
    for (int i = 0; i < inner_begin; ++i) out[first + i] = along<Axis>(u, i, j, k);
    for (int i = inner_begin; i < inner_end; ++i)
      out[first + i] = between_cells<Axis>(i, j, k, courant(u, first + i), below_inside, above_inside);
    for (int i = inner_end; i < n; ++i) out[first + i] = along<Axis>(u, i, j, k);
  }
#endif

 private:
  // u dt / dx at face f of u's lattice.
  DP_HD_INLINE double courant(const float* u, std::size_t f) const { return static_cast<double>(u[f]) * dt / cells.grid.dx; }

  // A face on the domain's boundary: an open one lets its cell's vapor out
  // and the ambient vapor in.
  DP_HD_INLINE double on_domain_face(int axis, const FaceSides& s, double c) const {
    const std::size_t inner = s.lo ? s.cell_lo : s.cell_hi;
    if (c == 0.0 || !cells.faces.open(axis, s.lo ? 1 : 0) || !carries_air(cells.kind[inner])) return 0.0;
    const bool leaving = s.lo ? c > 0 : c < 0;
    return c * (leaving ? vapor[inner] : ambient_vapor);
  }

  // Face (i, j, k) between two cells, a along Axis; whether cells a - 2
  // and a + 1 lie inside is given. Every value is read and computed for
  // both directions of flow and the result selected, with no branch: the
  // direction and the limiter's cases change from face to face
  // (mispredicted branches were most of this pass's time), and g++
  // vectorises a row of such faces (row()). The selected values are those
  // of the branching form for finite vapor.
  template <int Axis>
  DP_HD_INLINE double between_cells(int i, int j, int k, double c, bool below_inside, bool above_inside) const {
    const MacGrid& g = cells.grid;
    const std::ptrdiff_t stride = Axis == 0 ? 1 : (Axis == 1 ? static_cast<std::ptrdiff_t>(g.nx) : static_cast<std::ptrdiff_t>(g.nx) * g.ny);
    const std::size_t hi = g.cell(i, j, k), lo = hi - stride;
    // The cell behind the upwind one limits the slope if it lies inside and
    // carries air: cell a - 2 for forward flow, a + 1 for backward. Outside,
    // the upwind cell stands in for it, read but not used.
    const std::size_t below = lo - (below_inside ? stride : 0), above = hi + (above_inside ? stride : 0);
    const double v_below = vapor[below], v_lo = vapor[lo], v_hi = vapor[hi], v_above = vapor[above];
    const bool air_below = carries_air(cells.kind[below]), air_lo = carries_air(cells.kind[lo]),
               air_hi = carries_air(cells.kind[hi]), air_above = carries_air(cells.kind[above]);
    const bool carries = air_lo & air_hi;
    const bool forward = c > 0;
    const double up = forward ? v_lo : v_hi, down = forward ? v_hi : v_lo, behind = forward ? v_below : v_above;
    const bool limits = forward ? below_inside & air_below : above_inside & air_above;
    const double rise = up - behind, fall = down - up;
    const double slope = keep_if(minmod(rise, fall), limits);
    const double flux = c * (up + 0.5 * (1.0 - fabs(c)) * slope);
    return keep_if(flux, carries & (c != 0.0));
  }
};

// The speed (m/s) at which a cell's faces carry its vapor away: the sum of
// its outward face velocities. A face value is at most 1.5 times its upwind
// cell's (the limited slope is at most that cell's value), so a cell loses at
// most 1.5 (dt / dx) times this speed times its vapor in a sub-step, and
// stays positive while (dt / dx) times it is at most 2/3. Per cell, this
// bound is tighter than the sum of the three axes' largest speeds, which
// two different cells may hold. The launcher's max_3d finds the grid's
// largest: per cell on the GPU, per row (row_max) on the CPU.
struct CellOutflowSpeed {
  MacGrid grid;
  const float* u;
  const float* v;
  const float* w;
  DP_HD float operator()(int i, int j, int k) const {
    const float x = positive_part(-u[grid.face(0, i, j, k)]) + positive_part(u[grid.face(0, i + 1, j, k)]);
    const float y = positive_part(-v[grid.face(1, i, j, k)]) + positive_part(v[grid.face(1, i, j + 1, k)]);
    const float z = positive_part(-w[grid.face(2, i, j, k)]) + positive_part(w[grid.face(2, i, j, k + 1)]);
    return x + y + z;
  }
#if !defined(__CUDA_ARCH__)
  // The largest over cells 0 .. n - 1 of row (j, k). Every speed is a sum
  // of positive parts: +0, positive or +inf, never NaN or -0, so its bits
  // as an integer order as the floats do. g++ vectorises an integer max; a
  // float one it keeps scalar unless told that no NaN and no -0 occur.
  DP_HOST_INLINE float row_max(int n, int j, int k) const {
    std::int32_t largest = 0;
    for (int i = 0; i < n; ++i) {
      const std::int32_t s = bits_of((*this)(i, j, k));
      largest = s > largest ? s : largest;
    }
    return from_bits(largest);
  }
#endif
  // max(s, 0), 0 for NaN as fmaxf gives; a compare, where g++ calls libm's
  // fmaxf unless told that no NaN occurs.
  DP_HD static float positive_part(float s) { return s > 0.0f ? s : 0.0f; }
};

// Each face of axis Axis's flux, once (the two cells beside it read the
// same value).
template <int Axis>
struct ComputeVaporFlux {
  VaporFaceFlux flux;
  const float* u;
  double* out;
  DP_HD void operator()(int i, int j, int k) const {
    out[flux.cells.grid.face(Axis, i, j, k)] = flux.template along<Axis>(u, i, j, k);
  }
#if !defined(__CUDA_ARCH__)
  DP_HOST_INLINE void whole_row(int n, int j, int k) const { flux.template row<Axis>(u, out, n, j, k); }
#endif
};

// rho_c += sum of fluxes in - fluxes out, over its six faces (gather).
struct TransportVapor {
  MacGrid grid;
  const double* vapor;
  const double* flux_x;
  const double* flux_y;
  const double* flux_z;
  double* out;

  DP_HD void operator()(int i, int j, int k) const {
    const std::size_t c = grid.cell(i, j, k);
    double change = 0.0;
    change += flux_x[grid.face(0, i, j, k)] - flux_x[grid.face(0, i + 1, j, k)];
    change += flux_y[grid.face(1, i, j, k)] - flux_y[grid.face(1, i, j + 1, k)];
    change += flux_z[grid.face(2, i, j, k)] - flux_z[grid.face(2, i, j, k + 1)];
    out[c] = vapor[c] + change;
  }
};

// Vapor mass (kg) through the domain's boundary faces in one sub-step,
// `entering` or leaving, for the ledger: b runs over boundary_face_count
// (air/boundary_faces.h); closed faces carry no flux.
struct OpenFaceVaporMass {
  MacGrid grid;
  const double* flux_x;
  const double* flux_y;
  const double* flux_z;
  bool entering;

  DP_HD double operator()(std::size_t b) const {
    const BoundaryFace face = boundary_face(grid, b);
    const double* flux = face.axis == 0 ? flux_x : (face.axis == 1 ? flux_y : flux_z);
    // Outward flux is +G on the max side, -G on the min side.
    const double outward = face.high ? flux[face.face] : -flux[face.face];
    return side(outward) * static_cast<double>(grid.cell_volume());
  }
  DP_HD double side(double outward) const { return entering ? (outward < 0 ? -outward : 0.0) : (outward > 0 ? outward : 0.0); }
};

}  // namespace dp
