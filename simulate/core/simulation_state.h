#pragma once
// Everything a simulation carries from one step to the next, copied to the
// host: what a checkpoint holds (docs/file-formats.md). Restoring it into a
// simulation built from the same setup continues the run bit for bit; what
// is not here is either static (rebuilt from the setup: rigid positions and
// volumes, texel geometry, neighbourhoods of static objects) or recomputed
// at the start of every step before it is read (neighbour lists, air cell
// kinds, coupling stencils). The stochastic rounding of the coupling draws
// its coins from (particle id, step), so the step count is its RNG state.
#include <cstdint>
#include <vector>

#include "air/air_state.h"
#include "coupling/water_ledger.h"
#include "math/vec3.h"

namespace dp {

struct LiquidState {
  // In the core's current order (the order of the last sort or adaptivity).
  std::vector<Vec3> position, velocity;
  std::vector<float> temperature;        // K
  std::vector<std::uint32_t> mass_units; // sph/mass_units.h
  std::vector<std::uint32_t> id;
  // The last step's values, read by snapshots (frames written right after a
  // restore show them); the pressures also by a warm-started solve.
  std::vector<float> density, pressure, surface_area;
  std::uint32_t next_id = 0;             // for emitted particles
};

struct SurfaceState {
  std::vector<std::uint64_t> mass_units;  // m_t, texel units
  std::vector<float> temperature;         // K
  std::vector<float> wetting;             // wetting history
};

struct AirGridState {
  std::vector<float> u, v, w;                // face velocities, m/s
  std::vector<float> temperature_excess;     // T - T_amb per cell, K (stored as the grid holds it)
  std::vector<double> vapor;                 // kg/m^3 per cell
  std::vector<float> pressure;               // the projection's last phi, its next first guess
  std::vector<std::uint8_t> kind;            // the last classification (read by snapshots)
  AirLedger ledger;
};

struct SimulationState {
  std::int64_t steps = 0;
  std::int64_t settling_steps = 0;    // taken by Simulation::settle before step 1
  double time = 0;                    // s
  float last_max_acceleration = 0;    // m/s^2, bounds the next CFL step
  float converged_step_limit = 1e30f; // s, sph/time_step.h: ConvergedStepLimit
  std::uint64_t emitted_particles = 0;
  std::uint64_t left_domain_particles = 0, left_domain_units = 0;  // DomainLeaving::Remove, exact
  // Exact unit totals of the coupling (128-bit, as two halves).
  std::uint64_t liquid_to_air_lo = 0, texels_to_air_lo = 0;
  std::int64_t liquid_to_air_hi = 0, texels_to_air_hi = 0;
  WaterLedger initial_water;          // the ledger at construction
  LiquidState liquid;
  std::vector<float> rigid_temperature;  // K, in the core's rigid order
  std::vector<SurfaceState> surfaces;    // in the order of SimulationSetup::surfaces
  bool has_air = false;
  AirGridState air;
};

}  // namespace dp
