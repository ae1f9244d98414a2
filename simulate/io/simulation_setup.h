#pragma once
// Turns a validated scene into the core's plain-number setup: liquid blocks
// filled with particles, rigid meshes sampled into boundary particles.
#include "scene.h"
#include "simulation.h"

namespace dp::io {

// Loads the rigid meshes (throws naming the mesh file on failure).
SimulationSetup make_simulation_setup(const Scene& scene);

// The air section's core settings (vapor already a density, kelvin).
AirSettings make_air_settings(const AirSectionSettings& air);

// Particles on a cubic lattice of the given spacing, cell-centred in the block.
std::vector<Vec3> fill_block(const LiquidBlock& block, double spacing);

}  // namespace dp::io
