#pragma once
// What the air phase reports and hands out: its state copied to the host
// (for frames and tests), its vapor ledger and what one step did.
#include <cstdint>
#include <vector>

#include "air/cell_kind.h"
#include "air/mac_grid.h"
#include "math/vec3.h"

namespace dp {

// Where vapor mass (kg) entered and left the grid since the start. The grid
// holds initial + inflow_gain + open_in - open_out + exchanged, to rounding.
struct AirLedger {
  double initial = 0;      // at construction
  double inflow_gain = 0;  // resetting inflow cells to their prescribed vapor (may be negative)
  double open_in = 0;      // through open domain faces, entering
  double open_out = 0;     // through open domain faces, leaving
  double exchanged = 0;    // added by the coupling with particles and textures (paper Sec. 6)
  double expected_mass() const { return initial + inflow_gain + open_in - open_out + exchanged; }
};

// Wall clock of each part of one air step (s), in the step's order; zero
// unless AirSettings::time_parts is set.
struct AirStepSeconds {
  double inflows = 0;      // inflow cells and face velocities at walls
  double vapor = 0;        // conservative transport
  double temperature = 0;  // advection
  double forces = 0;       // buoyancy and vorticity confinement
  double velocity = 0;     // advection
  double diffusion = 0;    // heat and vapor
  double projection = 0;   // unknowns, right-hand side, PCG, gradient
};

struct AirStepReport {
  int projection_iterations = 0;
  float projection_residual = 0;  // |r|_2 / |b|_2
  int advection_substeps = 0;     // of the conservative vapor transport
  int diffusion_substeps = 0;
  AirStepSeconds seconds;
};

// The grid's state on the host. Vapor is kept in double (see AirGrid).
struct AirSnapshot {
  MacGrid grid;
  std::vector<std::uint8_t> kind;  // CellKind per cell
  std::vector<double> vapor;       // kg/m^3 per cell
  std::vector<float> temperature;  // K per cell
  std::vector<float> u, v, w;      // m/s on the faces of x, y, z
  AirLedger ledger;

  // The velocity at the centre of cell (i, j, k), the mean of its faces.
  Vec3 cell_velocity(int i, int j, int k) const {
    return Vec3{0.5f * (u[grid.face(0, i, j, k)] + u[grid.face(0, i + 1, j, k)]),
                0.5f * (v[grid.face(1, i, j, k)] + v[grid.face(1, i, j + 1, k)]),
                0.5f * (w[grid.face(2, i, j, k)] + w[grid.face(2, i, j, k + 1)])};
  }
  double vapor_mass() const {
    double m = 0;
    for (double r : vapor) m += r;
    return m * grid.cell_volume();
  }
};

}  // namespace dp
