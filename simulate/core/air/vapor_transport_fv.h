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
#include "air/boundary_conditions.h"
#include "air/cell_kind.h"

namespace dp {

DP_HD_INLINE double minmod(double a, double b) { return a * b <= 0.0 ? 0.0 : (fabs(a) < fabs(b) ? a : b); }

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
  DP_HD double along(const float* u, int i, int j, int k) const {
    constexpr int axis = Axis;
    const MacGrid& g = cells.grid;
    const FaceSides s = face_sides(g, axis, i, j, k);
    const std::size_t f = g.face(axis, i, j, k);
    const double c = static_cast<double>(u[f]) * dt / g.dx;
    if (c == 0.0) return 0.0;
    if (!(s.lo && s.hi)) {
      const std::size_t inner = s.lo ? s.cell_lo : s.cell_hi;
      if (!cells.faces.open(axis, s.lo ? 1 : 0) || !carries_air(cells.kind[inner])) return 0.0;
      const bool leaving = s.lo ? c > 0 : c < 0;
      return c * (leaving ? vapor[inner] : ambient_vapor);
    }
    // Between two cells: written with selects rather than branches (the
    // flow's direction and the limiter's cases change from face to face, and
    // mispredicted branches were most of this pass's time); the values are
    // those of the branching form for finite vapor.
    const bool carries = carries_air(cells.kind[s.cell_lo]) && carries_air(cells.kind[s.cell_hi]);
    const bool forward = c > 0;
    const std::size_t up = forward ? s.cell_lo : s.cell_hi, down = forward ? s.cell_hi : s.cell_lo;
    // The cell behind the upwind one (face a is the low face of cell a:
    // cell a - 2 for forward flow, a + 1 for backward), if it lies inside and
    // carries air, limits the slope; elsewhere the upwind cell stands in for
    // it, read but not used.
    const int a = axis == 0 ? i : (axis == 1 ? j : k);
    const std::ptrdiff_t stride = axis == 0 ? 1 : (axis == 1 ? static_cast<std::ptrdiff_t>(g.nx) : static_cast<std::ptrdiff_t>(g.nx) * g.ny);
    const bool behind_inside = forward ? a >= 2 : a + 1 < g.n(axis);
    const std::size_t behind = behind_inside ? (forward ? s.cell_lo - stride : s.cell_hi + stride) : up;
    const bool limits = behind_inside && carries_air(cells.kind[behind]);
    const double rise = vapor[up] - vapor[behind], fall = vapor[down] - vapor[up];
    const double slope = limits ? minmod(rise, fall) : 0.0;
    const double flux = c * (vapor[up] + 0.5 * (1.0 - fabs(c)) * slope);
    return carries ? flux : 0.0;
  }
};

// The speed (m/s) at which a cell's faces carry its vapor away: the sum of
// its outward face velocities. A face value is at most 1.5 times its upwind
// cell's (the limited slope is at most that cell's value), so a cell loses at
// most 1.5 (dt / dx) times this speed times its vapor in a sub-step, and
// stays positive while (dt / dx) times it is at most 2/3. Per cell, this
// bound is tighter than the sum of the three axes' largest speeds, which
// two different cells may hold. Called per row of cells along x (row =
// j + ny k), it gives the row's largest, so that a max over rows finds the
// grid's without dividing a cell index for every cell.
struct CellOutflowSpeed {
  MacGrid grid;
  const float* u;
  const float* v;
  const float* w;
  DP_HD float operator()(std::size_t row) const {
    const int j = static_cast<int>(row % grid.ny), k = static_cast<int>(row / grid.ny);
    float largest = 0.0f;
    for (int i = 0; i < grid.nx; ++i) {
      const float s = at(i, j, k);
      largest = s > largest ? s : largest;
    }
    return largest;
  }
  DP_HD float at(int i, int j, int k) const {
    const float x = positive_part(-u[grid.face(0, i, j, k)]) + positive_part(u[grid.face(0, i + 1, j, k)]);
    const float y = positive_part(-v[grid.face(1, i, j, k)]) + positive_part(v[grid.face(1, i, j + 1, k)]);
    const float z = positive_part(-w[grid.face(2, i, j, k)]) + positive_part(w[grid.face(2, i, j, k + 1)]);
    return x + y + z;
  }
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
// `entering` or leaving, for the ledger. Summed over the boundary faces
// alone (closed ones carry no flux): index b runs over the six sides in the
// order x-, x+, y-, y+, z-, z+, each side's faces in its own row order.
struct OpenFaceVaporMass {
  MacGrid grid;
  const double* flux_x;
  const double* flux_y;
  const double* flux_z;
  bool entering;

  DP_HD static std::size_t side_count(const MacGrid& g, int axis) {
    return axis == 0 ? static_cast<std::size_t>(g.ny) * g.nz
                     : (axis == 1 ? static_cast<std::size_t>(g.nx) * g.nz : static_cast<std::size_t>(g.nx) * g.ny);
  }
  DP_HD static std::size_t face_count(const MacGrid& g) { return 2 * (side_count(g, 0) + side_count(g, 1) + side_count(g, 2)); }

  DP_HD double operator()(std::size_t b) const {
    const MacGrid& g = grid;
    int axis = 0;
    while (b >= 2 * side_count(g, axis)) b -= 2 * side_count(g, axis++);
    const std::size_t per_side = side_count(g, axis);
    const bool high = b >= per_side;
    const std::size_t m = high ? b - per_side : b;
    // The side's faces as a 2-D array over the other two axes, first one fastest.
    const int n0 = axis == 0 ? g.ny : g.nx;
    const int p = static_cast<int>(m % n0), q = static_cast<int>(m / n0);
    const int at = high ? g.n(axis) : 0;
    const std::size_t f = axis == 0 ? g.face(0, at, p, q) : (axis == 1 ? g.face(1, p, at, q) : g.face(2, p, q, at));
    const double* flux = axis == 0 ? flux_x : (axis == 1 ? flux_y : flux_z);
    // Outward flux is +G on the max side, -G on the min side.
    const double outward = high ? flux[f] : -flux[f];
    return side(outward) * static_cast<double>(g.cell_volume());
  }
  DP_HD double side(double outward) const { return entering ? (outward < 0 ? -outward : 0.0) : (outward > 0 ? outward : 0.0); }
};

}  // namespace dp
