#pragma once
// Static particle lattices sorted into the neighbour grid, for the heat
// conduction tests (shared with the other model tests).
#include "../sorted_particles.h"

namespace dp::heat_test {
using test::grid_around;
using test::lattice_block;
using test::sort_into;
using test::SortedSet;
}  // namespace dp::heat_test
