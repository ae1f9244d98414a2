#pragma once
// What occupies an air cell (paper Alg. 1 line 7) and how the domain's six
// faces behave. Only air and inflow cells carry the air's flow; rigid and
// liquid cells are walls at rest for it (docs/paper-map.md, departures).
#include <cstdint>

#include "air/mac_grid.h"
#include "backend/host_device.h"

namespace dp {

enum CellKind : std::uint8_t { kAirCell = 0, kSolidCell = 1, kLiquidCell = 2, kInflowCell = 3 };

// Cells whose vapor and heat move with the air: air and inflow cells.
DP_HD inline bool carries_air(std::uint8_t kind) { return kind == kAirCell || kind == kInflowCell; }

// Bit 2*axis + side set: that face of the domain is open (outflow, ambient
// air may enter); clear: a closed wall.
struct DomainFaces {
  unsigned open_mask = 0;
  DP_HD bool open(int axis, int side) const { return (open_mask >> (2 * axis + side)) & 1u; }
  DP_HD bool any_open() const { return open_mask != 0; }
};

// The cells of the grid with their kinds, as the kernels read them.
struct CellKinds {
  MacGrid grid;
  const std::uint8_t* kind;
  DomainFaces faces;

  DP_HD std::uint8_t at(int i, int j, int k) const { return kind[grid.cell(i, j, k)]; }
  // The neighbour of (i, j, k) one step along `axis` in direction `side`
  // (0: minus, 1: plus); false when it lies outside the domain.
  DP_HD bool neighbour(int i, int j, int k, int axis, int side, int& ni, int& nj, int& nk) const {
    const int d = side ? 1 : -1;
    ni = i + (axis == 0 ? d : 0);
    nj = j + (axis == 1 ? d : 0);
    nk = k + (axis == 2 ? d : 0);
    return grid.inside(ni, nj, nk);
  }
};

}  // namespace dp
