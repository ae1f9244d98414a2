#pragma once
// How the pressure preconditioner's V-cycle (multigrid_mcadams2010.h) is
// laid out over launches. A plain setting, so that AirSettings can carry a
// benchmark's choice.
#include <cstddef>

namespace dp {

// How a V-cycle's passes are laid out over launches; the same arithmetic
// in every layout, so the same bits on one backend.
struct CycleLayout {
  // Restriction and prolongation in one pass each (RestrictWhole,
  // ProlongWhole) instead of three separable ones: on the GPU a pass over
  // a level of 32^3 or fewer cells is mostly its launch; on the CPU the
  // separable passes vectorise.
  bool whole_transfers = false;
  // Levels of at most this many cells run, with all the coarser ones, in one
  // call of Exec::in_one_block (one GPU thread block, a barrier between
  // passes, one launch per V-cycle for them all); 0: none.
  std::size_t one_block_cells = 0;
};

}  // namespace dp
