#pragma once
// Alg. 1 line 8's boundary conditions. A face is free (the flow and the
// pressure projection decide it) when it separates two air cells, or lies on
// an open domain face next to an air cell. Every other face is prescribed:
// the inflow velocity where it touches an inflow cell, else zero (closed
// domain walls, rigid and liquid cells: no flow through them).
#include "air/air_settings.h"
#include "air/cell_kind.h"

namespace dp {

// The two cells a face separates; `lo`/`hi` is false where that side lies
// outside the domain.
struct FaceSides {
  bool lo, hi;
  std::size_t cell_lo, cell_hi;
};

// The same for face (i, j, k) of `axis`.
DP_HD inline FaceSides face_sides(const MacGrid& g, int axis, int i, int j, int k) {
  const int a = axis == 0 ? i : (axis == 1 ? j : k);
  FaceSides s;
  s.lo = a > 0;
  s.hi = a < g.n(axis);
  s.cell_lo = s.lo ? g.cell(i - (axis == 0), j - (axis == 1), k - (axis == 2)) : 0;
  s.cell_hi = s.hi ? g.cell(i, j, k) : 0;
  return s;
}

// True where the flow and the projection decide the face's velocity.
DP_HD inline bool face_is_free(const CellKinds& cells, int axis, const FaceSides& s) {
  if (s.lo && s.hi) return cells.kind[s.cell_lo] == kAirCell && cells.kind[s.cell_hi] == kAirCell;
  const std::size_t inner = s.lo ? s.cell_lo : s.cell_hi;
  return cells.faces.open(axis, s.lo ? 1 : 0) && cells.kind[inner] == kAirCell;
}

// The faces of axis Axis (a compile-time axis folds the index arithmetic).
// Each face's verdict is also recorded (`prescribed`, `value`), so that
// ReapplyPrescribedFaces can enforce it again while the cells' kinds stay.
template <int Axis>
struct EnforceFaceVelocity {
  static constexpr int axis = Axis;
  CellKinds cells;
  const std::uint8_t* inflow_of_cell;  // 0: none, else index + 1
  const AirInflow* inflows;
  float* u;
  std::uint8_t* prescribed;  // per face: 1 where enforced
  float* value;              // per face: the enforced velocity (free faces: 0)

  DP_HD void operator()(int i, int j, int k) const {
    const std::size_t f = cells.grid.face(axis, i, j, k);
    const FaceSides s = face_sides(cells.grid, axis, i, j, k);
    const bool free = face_is_free(cells, axis, s);
    const float v = free ? 0.0f : prescribed_velocity(s);
    if (!free) u[f] = v;
    prescribed[f] = free ? 0 : 1;
    value[f] = v;
  }

  // The velocity a face that is not free holds.
  DP_HD float prescribed_velocity(const FaceSides& s) const {
    // Walls (closed faces, rigid and liquid cells) win over inflows.
    const bool wall_lo = s.lo ? (cells.kind[s.cell_lo] == kSolidCell || cells.kind[s.cell_lo] == kLiquidCell)
                              : !cells.faces.open(axis, 0);
    const bool wall_hi = s.hi ? (cells.kind[s.cell_hi] == kSolidCell || cells.kind[s.cell_hi] == kLiquidCell)
                              : !cells.faces.open(axis, 1);
    if (wall_lo || wall_hi) return 0.0f;
    const int in_lo = s.lo ? inflow_of_cell[s.cell_lo] : 0, in_hi = s.hi ? inflow_of_cell[s.cell_hi] : 0;
    const int n = in_hi ? in_hi : in_lo;
    return n ? inflows[n - 1].velocity[axis] : 0.0f;
  }
};

// EnforceFaceVelocity's verdicts applied again, face by face: the same
// values, without classifying each face anew (three times a step, on every
// face of the grid, that took more time than buoyancy). Loads without a
// condition and a select, so that the CPU vectorises it.
struct ReapplyPrescribedFaces {
  const std::uint8_t* prescribed;
  const float* value;
  float* u;
  DP_HD void operator()(std::size_t f) const {
    const float flowing = u[f], held = value[f];
    u[f] = prescribed[f] ? held : flowing;
  }
};

// The vapor mass (kg) an inflow cell gains when its vapor is reset to the
// prescribed value: the inflow's contribution to the mass ledger.
struct InflowVaporGain {
  const std::uint8_t* inflow_of_cell;
  const AirInflow* inflows;
  const double* vapor;
  double cell_volume;
  DP_HD double operator()(std::size_t c) const {
    const int n = inflow_of_cell[c];
    return n ? (inflows[n - 1].vapor - vapor[c]) * cell_volume : 0.0;
  }
};

struct ApplyInflowScalars {
  const std::uint8_t* inflow_of_cell;
  const AirInflow* inflows;
  float ambient_temperature;
  double* vapor;
  float* temperature_excess;  // T - T_amb
  DP_HD void operator()(std::size_t c) const {
    const int n = inflow_of_cell[c];
    if (!n) return;
    vapor[c] = inflows[n - 1].vapor;
    temperature_excess[c] = inflows[n - 1].temperature - ambient_temperature;
  }
};

}  // namespace dp
