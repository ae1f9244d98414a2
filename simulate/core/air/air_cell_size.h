#pragma once
// The paper's rule for the air grid's cell size (Sec. 4.2): a cell must be
// larger than two support radii, so that the particles near a cell are
// found in its neighbours. Checked where a scene is read, to name the key,
// and again where a simulation is made.
#include "simulation.h"

namespace dp {

// Throws std::invalid_argument naming the cell size, the limit and the
// largest resolution that keeps to it.
void check_air_cell_size(const SimulationSetup& setup);

}  // namespace dp
