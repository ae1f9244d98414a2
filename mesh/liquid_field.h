#pragma once
// The liquid's distance field on a grid: Zhu-Bridson (paper Eq. 19),
// optionally with the wall corrections of Eq. 20-24, evaluated only in a
// narrow band around the particles. The grid is cut into blocks of 8^3
// nodes; a block is evaluated only when some particle lies within the kernel
// radius of it, every other node is "outside" (phi = R). In an active block
// each particle near it adds its kernel weights to the nodes within R of it
// (a gather per block: one task owns the block's nodes and visits its
// particles in a fixed order), so the field is bit-identical for any number
// of threads. Blocks run in parallel (TBB).
#include <cstddef>

#include "block_kernel_sums.h"
#include "contact_angle_correction.h"
#include "liquid_particles.h"
#include "scalar_grid.h"

namespace dp::mesh {


struct LiquidFieldCounts {
  std::size_t blocks = 0, active_blocks = 0;
  std::size_t blocks_near_walls = 0;  // active blocks within the walls' reach
  CorrectionCounts correction;
};

// `correction` may be null: the plain field of Eq. 19.
ScalarGrid sample_liquid_field(const LiquidParticles& particles, double kernel_radius, const GridBox& box,
                               const ContactAngleCorrection_HochstetterKolb2017* correction,
                               LiquidFieldCounts* counts = nullptr);

}  // namespace dp::mesh
