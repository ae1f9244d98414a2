#pragma once
// Alg. 1 line 7: cells holding a rigid particle are solid, cells holding a
// liquid particle liquid, the rest air; inflow regions are set by the scene.
// Rigid and inflow cells are static and found once (`StaticCellKinds`);
// liquid cells are found every step (`ClassifyCells`). Each cell asks the
// particles' neighbour grid (Green 2009) which particles lie in it: a gather,
// one writer per cell.
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

// Per step: static kinds, with air cells that hold a liquid particle liquid.
struct ClassifyCells {
  MacGrid grid;
  GridView liquid;  // position null: no liquid
  const std::uint8_t* static_kind;
  std::uint8_t* kind;

  DP_HD void operator()(int i, int j, int k) const {
    const std::size_t c = grid.cell(i, j, k);
    const std::uint8_t s = static_kind[c];
    if (s != kAirCell) {
      kind[c] = s;
      return;
    }
    const Vec3 lo = grid.origin + grid.dx * Vec3{static_cast<float>(i), static_cast<float>(j), static_cast<float>(k)};
    kind[c] = any_particle_in_box(liquid, lo, lo + Vec3{grid.dx, grid.dx, grid.dx}) ? kLiquidCell : kAirCell;
  }
};

}  // namespace dp
