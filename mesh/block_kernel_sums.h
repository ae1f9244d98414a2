#pragma once
// The kernel sums of Eq. 19 at every node of one field block, gathered
// particle by particle. Rows along x are stored padded to the full block
// width so that each row is one fixed-length loop the compiler turns into
// whole vector registers; nodes outside a particle's kernel add exact zeros,
// so padding and masking change no sum.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "liquid_particles.h"
#include "zhu_bridson.h"

namespace dp::mesh {

inline constexpr int kFieldBlock = 8;  // nodes per block edge

struct BlockKernelSums {
  int ny = 0, nz = 0;  // rows are always kFieldBlock nodes long
  std::vector<double> weight, offset_x, offset_y, offset_z, radius, velocity_x, velocity_y, velocity_z;

  std::size_t node(int i, int j, int k) const { return (std::size_t(k) * ny + j) * kFieldBlock + i; }
  KernelSums at(std::size_t n) const;
};

// Sums over `near` (in that order) at the nodes origin + voxel_size * (i, j, k),
// 0 <= j < ny, 0 <= k < nz, 0 <= i < kFieldBlock, velocities left out (most
// blocks never need them).
BlockKernelSums gather_block_kernel_sums(Vec3d origin, int ny, int nz, double voxel_size, const LiquidParticles& p,
                                         const std::vector<std::uint32_t>& near, double kernel_radius);

// Adds the velocity sums to `sums`, gathered with the same arguments, where
// the particles have velocities; each row's velocity sums are accumulated
// on their own, in the same order, so they do not depend on when.
void add_block_velocity_sums(BlockKernelSums& sums, Vec3d origin, double voxel_size, const LiquidParticles& p,
                             const std::vector<std::uint32_t>& near, double kernel_radius);

}  // namespace dp::mesh
