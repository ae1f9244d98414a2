#pragma once
// Vorticity confinement (Fedkiw, Stam & Jensen 2001, Sec. 3.3), which the
// paper uses to keep the coarse grid's small eddies (Sec. 4.2):
//   omega = curl u,  N = grad|omega| / |grad|omega||,  f = epsilon dx (N x omega).
// Derivatives are central differences at cell centres, one-sided next to
// walls and non-air cells. epsilon is in 1/s in SI units.
#include "air/cell_kind.h"
#include "air/mac_grid.h"
#include "air/poisson_level.h"
#include "math/keep_if.h"

namespace dp {

// The velocity at cell centres: the mean of each component's two faces.
struct CellCentredVelocity {
  MacGrid grid;
  const float* u;
  const float* v;
  const float* w;
  Vec3* out;
  DP_HD void operator()(std::size_t c) const {
    int i, j, k;
    grid.cell_coords(c, i, j, k);
    (*this)(i, j, k);
  }
  DP_HD void operator()(int i, int j, int k) const {
    out[grid.cell(i, j, k)] = Vec3{0.5f * (u[grid.face(0, i, j, k)] + u[grid.face(0, i + 1, j, k)]),
                  0.5f * (v[grid.face(1, i, j, k)] + v[grid.face(1, i, j + 1, k)]),
                  0.5f * (w[grid.face(2, i, j, k)] + w[grid.face(2, i, j, k + 1)])};
  }
};

// 1/dx and 1/(2 dx), the scales of a one-sided and a central difference,
// found once per pass rather than divided out per derivative.
struct DifferenceScales {
  float one_step, two_steps;
};
DP_HD inline DifferenceScales difference_scales(float dx) { return DifferenceScales{1.0f / dx, 1.0f / (2.0f * dx)}; }

// d value / d x_axis at an air cell, from its air neighbours: central
// between two, one-sided next to one, 0 without. `at` points to the cell's
// value in a padded field (padded_field.h), `stride` is the axis' index
// step, and `air` the cell's air neighbours as the pressure stencil marks
// them (PoissonLevel::stencil: bit 2 axis + side, the unknowns being the
// air cells). Both neighbours are loaded and the bits select, without a
// branch; the values are those of the branching form.
// The selects are made on the bits (pick_if): as plain selects, g++ split
// the cell's cases into branches, one subtraction in each, which kept the
// loop scalar.
DP_HD_INLINE float air_derivative(const float* at, std::ptrdiff_t stride, unsigned air, int axis, DifferenceScales scales) {
  const unsigned minus = (air >> (2 * axis)) & 1u, plus = (air >> (2 * axis + 1)) & 1u;
  const float here = at[0], above = at[stride], below = at[-stride];
  return (pick_if(plus, above, here) - pick_if(minus, below, here)) * pick_if(plus & minus, scales.two_steps, scales.one_step);
}

// The same for each component of a vector field, read component by
// component: g++ vectorises no loop that copies a Vec3 whole.
DP_HD_INLINE Vec3 air_derivative(const Vec3* at, std::ptrdiff_t stride, unsigned air, int axis, DifferenceScales scales) {
  const unsigned minus = (air >> (2 * axis)) & 1u, plus = (air >> (2 * axis + 1)) & 1u;
  const float scale = pick_if(plus & minus, scales.two_steps, scales.one_step);
  const auto along = [&](float here, float above, float below) { return (pick_if(plus, above, here) - pick_if(minus, below, here)) * scale; };
  return Vec3{along(at[0].x, at[stride].x, at[-stride].x), along(at[0].y, at[stride].y, at[-stride].y),
              along(at[0].z, at[stride].z, at[-stride].z)};
}

// The index steps along x, y and z between a level's cells.
struct CellSteps {
  std::ptrdiff_t axis[3];
  DP_HD explicit CellSteps(const PoissonLevel& l) : axis{1, l.nx, static_cast<std::ptrdiff_t>(l.slab())} {}
};

// omega = curl u and |omega| at the air cells, +0 elsewhere. Every cell is
// computed (the padded field holds a neighbour for each) and the non-air
// ones cleared on the bits (keep_if), with no branch, so the loop
// vectorises; the values are those of returning early.
struct ComputeVorticity {
  PoissonLevel air;  // the finest pressure level: its stencil marks the air neighbours
  DifferenceScales scales;
  const Vec3* velocity;  // cell-centred, padded by a slab
  Vec3* omega;
  float* omega_norm;
  DP_HD void operator()(std::size_t c) const { curl_at(c, velocity, omega, omega_norm); }
#if !defined(__CUDA_ARCH__)
  // Cells begin .. end - 1 (CpuExec::parallel_for), the fields as restrict
  // pointers (TakesWholeRanges).
  DP_HOST_INLINE void whole_range(std::size_t begin, std::size_t end) const { curl_over(begin, end, velocity, omega, omega_norm); }
  DP_HOST_INLINE void curl_over(std::size_t begin, std::size_t end, const Vec3* __restrict v, Vec3* __restrict w,
                                float* __restrict w_norm) const {
    for (std::size_t c = begin; c < end; ++c) curl_at(c, v, w, w_norm);
  }
#endif

 private:
  DP_HD_INLINE void curl_at(std::size_t c, const Vec3* v, Vec3* w, float* w_norm) const {
    const unsigned bits = air.stencil[c];
    const unsigned is_air = (bits & PoissonLevel::kStencilUnknown) != 0;
    const CellSteps steps(air);
    const Vec3* at = v + c;
    const Vec3 dx = air_derivative(at, steps.axis[0], bits, 0, scales);
    const Vec3 dy = air_derivative(at, steps.axis[1], bits, 1, scales);
    const Vec3 dz = air_derivative(at, steps.axis[2], bits, 2, scales);
    const Vec3 curl{dy.z - dz.y, dz.x - dx.z, dx.y - dy.x};
    w[c].x = keep_if(curl.x, is_air);  // by component, as air_derivative reads
    w[c].y = keep_if(curl.y, is_air);
    w[c].z = keep_if(curl.z, is_air);
    w_norm[c] = keep_if(length(curl), is_air);
  }
};

// f = epsilon dx (N x omega) at the air cells where |omega| has a gradient,
// +0 elsewhere; computed for every cell and selected, as ComputeVorticity.
struct ComputeConfinementForce {
  PoissonLevel air;  // as in ComputeVorticity
  DifferenceScales scales;
  float dx;
  const Vec3* omega;
  const float* omega_norm;  // padded by a slab
  float epsilon;
  Vec3* force;
  DP_HD void operator()(std::size_t c) const { force_at(c, omega, omega_norm, force); }
#if !defined(__CUDA_ARCH__)
  // As ComputeVorticity::whole_range.
  DP_HOST_INLINE void whole_range(std::size_t begin, std::size_t end) const { force_over(begin, end, omega, omega_norm, force); }
  DP_HOST_INLINE void force_over(std::size_t begin, std::size_t end, const Vec3* __restrict w, const float* __restrict w_norm,
                                 Vec3* __restrict f) const {
    for (std::size_t c = begin; c < end; ++c) force_at(c, w, w_norm, f);
  }
#endif

 private:
  DP_HD_INLINE void force_at(std::size_t c, const Vec3* w, const float* w_norm, Vec3* out) const {
    const unsigned bits = air.stencil[c];
    const CellSteps steps(air);
    const float* at = w_norm + c;
    const Vec3 grad{air_derivative(at, steps.axis[0], bits, 0, scales), air_derivative(at, steps.axis[1], bits, 1, scales),
                    air_derivative(at, steps.axis[2], bits, 2, scales)};
    const float g = length(grad);
    // A flat |omega| has no direction to confine towards.
    const unsigned confines = ((bits & PoissonLevel::kStencilUnknown) != 0) & (g > 1e-20f);
    const Vec3 f = (epsilon * dx) * cross((1.0f / g) * grad, Vec3{w[c].x, w[c].y, w[c].z});
    out[c].x = keep_if(f.x, confines);  // by component, as air_derivative reads
    out[c].y = keep_if(f.y, confines);
    out[c].z = keep_if(f.z, confines);
  }
};

// u_a += dt f_a on one axis' faces, f the mean of the two cells' forces.
template <int Axis>
struct AddCellForceToFaces {
  static constexpr int axis = Axis;
  MacGrid grid;
  const Vec3* force;
  float dt;
  float* u;
  DP_HD void operator()(int i, int j, int k) const {
    const int a = (axis == 0 ? i : (axis == 1 ? j : k));
    const int lo = a > 0 ? a - 1 : 0, hi = a < grid.n(axis) ? a : a - 1;
    add(u, force, grid.face(axis, i, j, k), grid.cell(axis == 0 ? lo : i, axis == 1 ? lo : j, axis == 2 ? lo : k),
        grid.cell(axis == 0 ? hi : i, axis == 1 ? hi : j, axis == 2 ? hi : k));
  }
#if !defined(__CUDA_ARCH__)
  // Faces (0 .. n - 1, j, k) (CpuExec::parallel_for_3d): the two cells of
  // every inner face lie at fixed offsets from it along the row, so that
  // loop vectorises; the domain's faces along x go as operator() does.
  DP_HOST_INLINE void whole_row(int n, int j, int k) const { add_row(u, force, n, j, k); }
#endif

 private:
  DP_HD_INLINE void add(float* to, const Vec3* from, std::size_t f, std::size_t cell_lo, std::size_t cell_hi) const {
    // The axis' component read alone: g++ vectorises no loop that copies a Vec3.
    to[f] += dt * 0.5f * (from[cell_lo][axis] + from[cell_hi][axis]);
  }
#if !defined(__CUDA_ARCH__)
  DP_HOST_INLINE void add_row(float* __restrict to, const Vec3* __restrict from, int n, int j, int k) const {
    const std::size_t first = grid.face(axis, 0, j, k);
    if constexpr (axis == 0) {
      const std::size_t cell = grid.cell(0, j, k);
      (*this)(0, j, k);
      for (int i = 1; i < n - 1; ++i) add(to, from, first + i, cell + i - 1, cell + i);
      if (n > 1) (*this)(n - 1, j, k);
    } else {
      const int a = axis == 1 ? j : k;
      const int lo = a > 0 ? a - 1 : 0, hi = a < grid.n(axis) ? a : a - 1;
      const std::size_t cell_lo = grid.cell(0, axis == 1 ? lo : j, axis == 2 ? lo : k);
      const std::size_t cell_hi = grid.cell(0, axis == 1 ? hi : j, axis == 2 ? hi : k);
      for (int i = 0; i < n; ++i) add(to, from, first + i, cell_lo + i, cell_hi + i);
    }
  }
#endif
};

}  // namespace dp
