#pragma once
// Alg. 1 line 7: cells holding a rigid particle are solid, cells holding a
// liquid particle liquid, the rest air; inflow regions are set by the scene.
// Rigid and inflow cells are static and found once (`StaticCellKinds`):
// each cell asks the rigid particles' neighbour grid (Green 2009) which of
// them lie in it, a gather with one writer per cell. Liquid cells are
// found every step (`MarkLiquidCells`), from the liquid particles.
#include <cstdint>

#include "air/air_settings.h"
#include "air/cell_kind.h"
#include "air/mac_grid.h"
#include "sph/uniform_grid.h"

namespace dp {

// True when some particle of `set` lies in the box [lo, hi). Particles may
// have moved up to one neighbour cell since `set` was sorted, so the search
// reaches one cell further.
DP_HD inline bool any_particle_in_box(const GridView& set, Vec3 lo, Vec3 hi) {
  if (set.position == nullptr) return false;
  int i0, j0, k0, i1, j1, k1;
  set.grid.cell_of(lo, i0, j0, k0);
  set.grid.cell_of(hi, i1, j1, k1);
  i0 = i0 > 0 ? i0 - 1 : 0;
  j0 = j0 > 0 ? j0 - 1 : 0;
  k0 = k0 > 0 ? k0 - 1 : 0;
  i1 = i1 + 1 < set.grid.nx ? i1 + 1 : set.grid.nx - 1;
  j1 = j1 + 1 < set.grid.ny ? j1 + 1 : set.grid.ny - 1;
  k1 = k1 + 1 < set.grid.nz ? k1 + 1 : set.grid.nz - 1;
  // The box's cells all lie between its first and last cell in the grid's
  // linear order, and so do their particles: where that whole run is empty,
  // as it is for most cells far from the liquid, no row needs a look.
  if (set.cell_begin[set.grid.linear(i0, j0, k0)] >= set.cell_end[set.grid.linear(i1, j1, k1)]) return false;
  for (int k = k0; k <= k1; ++k)
    for (int j = j0; j <= j1; ++j) {
      // A row of cells along x is one contiguous run of particles.
      const std::uint32_t end = set.cell_end[set.grid.linear(i1, j, k)];
      for (std::uint32_t p = set.cell_begin[set.grid.linear(i0, j, k)]; p < end; ++p) {
        const Vec3 x = set.position[p];
        if (x.x >= lo.x && x.y >= lo.y && x.z >= lo.z && x.x < hi.x && x.y < hi.y && x.z < hi.z) return true;
      }
    }
  return false;
}

DP_HD inline bool inflow_contains(const AirInflow& in, Vec3 p) {
  if (in.shape == AirInflow::Shape::Box)
    return p.x >= in.box_min.x && p.y >= in.box_min.y && p.z >= in.box_min.z && p.x <= in.box_max.x &&
           p.y <= in.box_max.y && p.z <= in.box_max.z;
  const Vec3 d = p - in.center;
  const float along = dot(d, in.normal);
  const Vec3 radial = d - along * in.normal;
  return fabsf(along) <= 0.5f * in.thickness && length_squared(radial) <= in.radius * in.radius;
}

// The kinds that never change: solid where a rigid particle is, else the
// index+1 of the first inflow containing the cell centre, else air.
struct StaticCellKinds {
  MacGrid grid;
  GridView rigid;  // position null: no rigids
  std::uint8_t* kind;
  std::uint8_t* inflow;  // 0: none, else inflow index + 1
  const AirInflow* inflows;
  int inflow_count;

  DP_HD void operator()(std::size_t c) const {
    int i, j, k;
    grid.cell_coords(c, i, j, k);
    const Vec3 lo = grid.origin + grid.dx * Vec3{static_cast<float>(i), static_cast<float>(j), static_cast<float>(k)};
    const Vec3 hi = lo + Vec3{grid.dx, grid.dx, grid.dx};
    inflow[c] = 0;
    if (any_particle_in_box(rigid, lo, hi)) {
      kind[c] = kSolidCell;
      return;
    }
    const Vec3 center = grid.cell_center(i, j, k);
    for (int n = 0; n < inflow_count; ++n)
      if (inflow_contains(inflows[n], center)) {
        kind[c] = kInflowCell;
        inflow[c] = static_cast<std::uint8_t>(n + 1);
        return;
      }
    kind[c] = kAirCell;
  }
};

// The particles a step classifies the cells from.
struct ParticlePositions {
  const Vec3* position;
  std::size_t count;
};

// The cells along one axis whose span [lo, lo + dx), lo = origin + dx i,
// holds coordinate x, as any_particle_in_box tests it: the cell floor finds
// and, where rounding makes neighbouring spans overlap or leave a gap of an
// ulp, its neighbours by the same test. At most two; returns how many.
DP_HD_INLINE int cells_holding(float x, float origin, float dx, int n, int* cells) {
  const float f = floorf((x - origin) / dx);
  if (!(f >= -1.0f && f <= static_cast<float>(n))) return 0;  // far outside, or NaN
  const int c = static_cast<int>(f);
  int count = 0;
  for (int i = c - 1; i <= c + 1; ++i) {
    if (i < 0 || i >= n) continue;
    const float lo = origin + dx * static_cast<float>(i);
    if (x >= lo && x < lo + dx && count < 2) cells[count++] = i;
  }
  return count;
}

// Per step (Alg. 1 line 7), after every cell took its static kind: each
// liquid particle turns the air cells holding it liquid. A scatter, where
// the static kinds gather, because the liquid is small against the grid:
// asking every cell which particles lie in it walked the particles' grid
// 27 cells at a time for 262K cells, one of the larger parts of a 64^3 air
// step. A cell that several particles mark receives the same value from
// each, so the order of those writes changes nothing and the result is
// that of the per-cell box test (tested against any_particle_in_box).
struct MarkLiquidCells {
  MacGrid grid;
  ParticlePositions liquid;
  const std::uint8_t* static_kind;
  std::uint8_t* kind;

  DP_HD void operator()(std::size_t p) const {
    const Vec3 x = liquid.position[p];
    int ci[2], cj[2], ck[2];
    const int ni = cells_holding(x.x, grid.origin.x, grid.dx, grid.nx, ci);
    const int nj = cells_holding(x.y, grid.origin.y, grid.dx, grid.ny, cj);
    const int nk = cells_holding(x.z, grid.origin.z, grid.dx, grid.nz, ck);
    for (int a = 0; a < nk; ++a)
      for (int b = 0; b < nj; ++b)
        for (int d = 0; d < ni; ++d) {
          const std::size_t c = grid.cell(ci[d], cj[b], ck[a]);
          if (static_kind[c] == kAirCell) mark(kind + c);
        }
  }
  DP_HD_INLINE static void mark(std::uint8_t* k) {
#if defined(__CUDA_ARCH__)
    *k = kLiquidCell;
#else
    __atomic_store_n(k, static_cast<std::uint8_t>(kLiquidCell), __ATOMIC_RELAXED);  // a plain byte store, without a data race
#endif
  }
};

}  // namespace dp
