#pragma once
// Alg. 1 line 8's boundary conditions. A face is free (the flow and the
// pressure projection decide it) when it separates two air cells, or lies on
// an open domain face next to an air cell. Every other face is prescribed:
// the inflow velocity where it touches an inflow cell, else zero (closed
// domain walls, rigid and liquid cells: no flow through them).
#include <cstdint>
#include <vector>

#include "air/air_settings.h"
#include "air/cell_kind.h"
#include "math/keep_if.h"

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

// The table EnforceFaceVelocity reads along `axis` by a cell's
// inflow_of_cell entry: 0 for none, then each inflow's velocity.
inline std::vector<float> inflow_velocities_along(const std::vector<AirInflow>& inflows, int axis) {
  std::vector<float> table{0.0f};
  for (const AirInflow& in : inflows) table.push_back(in.velocity[axis]);
  return table;
}

// The faces of axis Axis (a compile-time axis folds the index arithmetic).
// Each face's verdict is also recorded (`prescribed`, `value`), so that
// ReapplyPrescribedFaces can enforce it again while the cells' kinds stay.
template <int Axis>
struct EnforceFaceVelocity {
  static constexpr int axis = Axis;
  CellKinds cells;
  const std::uint8_t* inflow_of_cell;  // 0: none, else index + 1
  const float* inflow_velocity;        // by inflow_of_cell: 0, then each inflow's velocity along Axis
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
    const bool wall_lo = s.lo ? is_wall(cells.kind[s.cell_lo]) : !cells.faces.open(axis, 0);
    const bool wall_hi = s.hi ? is_wall(cells.kind[s.cell_hi]) : !cells.faces.open(axis, 1);
    if (wall_lo || wall_hi) return 0.0f;
    const int in_lo = s.lo ? inflow_of_cell[s.cell_lo] : 0, in_hi = s.hi ? inflow_of_cell[s.cell_hi] : 0;
    return inflow_velocity[in_hi ? in_hi : in_lo];
  }

  // A rigid or liquid cell: no flow through its faces.
  DP_HD static unsigned is_wall(unsigned kind) { return (kind == kSolidCell) | (kind == kLiquidCell); }
  // The two cells of an inner face both carry air, which leaves it free.
  DP_HD static unsigned both_air(unsigned kind_lo, unsigned kind_hi) { return (kind_lo | kind_hi) == kAirCell; }

#if !defined(__CUDA_ARCH__)
  // Faces 0 .. n - 1 of row (j, k) (CpuExec::parallel_for_3d). Which faces
  // have a cell on both sides is decided once per row; those run as one
  // loop over consecutive cells, the verdict computed for every face and
  // selected on the bits (keep_if.h), which g++ vectorises. The same values
  // as face by face.
  DP_HOST_INLINE void whole_row(int n, int j, int k) const {
    const MacGrid& g = cells.grid;
    const int across = Axis == 1 ? j : k;  // the row's coordinate along Axis (y or z)
    if (Axis != 0 && (across == 0 || across == g.n(Axis))) {  // a domain face: one cell per face
      for (int i = 0; i < n; ++i) (*this)(i, j, k);
      return;
    }
    // Face i lies between cells lo0 + i and hi0 + i (along x: i - 1 and i).
    const std::size_t hi0 = g.cell(0, j, k);
    const std::size_t lo0 = Axis == 0 ? hi0 - 1 : g.cell(0, Axis == 1 ? j - 1 : j, Axis == 2 ? k - 1 : k);
    const std::size_t f0 = g.face(axis, 0, j, k);
    if (Axis == 0) (*this)(0, j, k);
    const int first = Axis == 0 ? 1 : 0, end = Axis == 0 ? n - 1 : n;
    if (inner_faces_without_inflow(first, end, f0, lo0, hi0)) inflow_faces(first, end, f0, lo0, hi0);
    if (Axis == 0) (*this)(n - 1, j, k);
  }

  // Faces f0 + i, i in [first, end), with +0 where an inflow cell sets the
  // velocity (the table lookup, a gather, would keep the loop scalar);
  // whether there was such a face.
  DP_HOST_INLINE bool inner_faces_without_inflow(int first, int end, std::size_t f0, std::size_t lo0, std::size_t hi0) const {
    const std::uint8_t* __restrict kind = cells.kind;
    float* __restrict out_u = u + f0;
    std::uint8_t* __restrict out_prescribed = prescribed + f0;
    float* __restrict out_value = value + f0;
    unsigned any_inflow = 0;
    for (int i = first; i < end; ++i) {
      const unsigned kind_lo = kind[lo0 + i], kind_hi = kind[hi0 + i];
      const unsigned free = both_air(kind_lo, kind_hi), wall = is_wall(kind_lo) | is_wall(kind_hi);
      any_inflow |= (free | wall) ^ 1u;
      out_u[i] = keep_if(out_u[i], free);
      out_prescribed[i] = static_cast<std::uint8_t>(free ^ 1u);
      out_value[i] = 0.0f;
    }
    return any_inflow != 0;
  }

  // The faces an inflow cell sets, between neither a wall nor two air cells.
  DP_HOST_INLINE void inflow_faces(int first, int end, std::size_t f0, std::size_t lo0, std::size_t hi0) const {
    for (int i = first; i < end; ++i) {
      const unsigned kind_lo = cells.kind[lo0 + i], kind_hi = cells.kind[hi0 + i];
      if (both_air(kind_lo, kind_hi) | is_wall(kind_lo) | is_wall(kind_hi)) continue;
      const int in_lo = inflow_of_cell[lo0 + i], in_hi = inflow_of_cell[hi0 + i];
      const float v = inflow_velocity[in_hi ? in_hi : in_lo];
      u[f0 + i] = v;
      value[f0 + i] = v;
    }
  }
#endif
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

// The cells inflows cover (inflow_of_cell not 0), in index order: the
// inflow passes visit these alone. Static, as the inflows are.
inline std::vector<std::uint32_t> inflow_cells_of(const std::vector<std::uint8_t>& inflow_of_cell) {
  std::vector<std::uint32_t> cells;
  for (std::size_t c = 0; c < inflow_of_cell.size(); ++c)
    if (inflow_of_cell[c]) cells.push_back(static_cast<std::uint32_t>(c));
  return cells;
}

// The vapor mass (kg) inflow cell c gains when its vapor is reset to the
// prescribed value: the inflow's contribution to the mass ledger. Run over
// inflow_cells_of's list (at_keys).
struct InflowVaporGain {
  const std::uint8_t* inflow_of_cell;
  const AirInflow* inflows;
  const double* vapor;
  double cell_volume;
  DP_HD double operator()(std::uint32_t c) const { return (inflows[inflow_of_cell[c] - 1].vapor - vapor[c]) * cell_volume; }
};

// Inflow cell c takes its inflow's vapor and temperature; over the same list.
struct ApplyInflowScalars {
  const std::uint8_t* inflow_of_cell;
  const AirInflow* inflows;
  float ambient_temperature;
  double* vapor;
  float* temperature_excess;  // T - T_amb
  DP_HD void operator()(std::uint32_t c) const {
    const AirInflow& in = inflows[inflow_of_cell[c] - 1];
    vapor[c] = in.vapor;
    temperature_excess[c] = in.temperature - ambient_temperature;
  }
};

}  // namespace dp
