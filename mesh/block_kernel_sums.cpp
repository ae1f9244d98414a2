#include "block_kernel_sums.h"

#include <algorithm>
#include <cmath>

namespace dp::mesh {

KernelSums BlockKernelSums::at(std::size_t n) const {
  KernelSums s;
  s.weight = weight[n];
  s.offset = {offset_x[n], offset_y[n], offset_z[n]};
  s.radius = radius[n];
  if (!velocity_x.empty()) s.velocity = {velocity_x[n], velocity_y[n], velocity_z[n]};
  return s;
}

namespace {

struct RowSums {
  double* weight;
  double* offset_x;
  double* offset_y;
  double* offset_z;
  double* radius;
};

// One particle's contribution to one row of kFieldBlock nodes: a fixed trip
// count and no branches, so it compiles to straight vector code.
inline void add_to_row(const RowSums& row, const double (&dx)[kFieldBlock], double dyz2, double dy, double dz,
                       double particle_radius, double inverse_r2) {
  for (int n = 0; n < kFieldBlock; ++n) {
    const double t = std::max(0.0, 1.0 - (dx[n] * dx[n] + dyz2) * inverse_r2);
    const double kernel = t * t * t;  // zhu_bridson_kernel
    row.weight[n] += kernel;
    row.offset_x[n] += kernel * dx[n];
    row.offset_y[n] += kernel * dy;
    row.offset_z[n] += kernel * dz;
    row.radius[n] += kernel * particle_radius;
  }
}

inline void add_velocity_to_row(double* vx, double* vy, double* vz, const double (&dx)[kFieldBlock], double dyz2,
                                Vec3d v, double inverse_r2) {
  for (int n = 0; n < kFieldBlock; ++n) {
    const double t = std::max(0.0, 1.0 - (dx[n] * dx[n] + dyz2) * inverse_r2);
    const double kernel = t * t * t;
    vx[n] += kernel * v.x;
    vy[n] += kernel * v.y;
    vz[n] += kernel * v.z;
  }
}

// The hot loop of the mesher; built for AVX2 as well where the CPU has it
// (chosen at load time), the portable build stays the default.
// The velocity sums are added row by row on their own, so gathering them in
// a later pass gives the same bits as gathering them with the rest.
__attribute__((target_clones("avx2", "default"))) void gather_into(
    BlockKernelSums& sums, Vec3d origin, double h, const LiquidParticles& p, const std::vector<std::uint32_t>& near,
    double kernel_radius, bool with_positions, bool with_velocity) {
  const double r2 = kernel_radius * kernel_radius, inverse_r2 = 1 / r2;
  for (std::uint32_t i : near) {
    // In block coordinates, so that offsets do not cancel large world coordinates.
    const Vec3d local = p.position[i] - origin;
    double dx[kFieldBlock];
    for (int n = 0; n < kFieldBlock; ++n) dx[n] = local.x - h * n;  // x_i - x
    const int k0 = std::max(0, int(std::ceil((local.z - kernel_radius) / h)));
    const int k1 = std::min(sums.nz - 1, int(std::floor((local.z + kernel_radius) / h)));
    for (int k = k0; k <= k1; ++k) {
      const double dz = local.z - h * k, dz2 = dz * dz;
      if (dz2 >= r2) continue;
      const double half_chord = std::sqrt(r2 - dz2);
      const int j0 = std::max(0, int(std::ceil((local.y - half_chord) / h)));
      const int j1 = std::min(sums.ny - 1, int(std::floor((local.y + half_chord) / h)));
      for (int j = j0; j <= j1; ++j) {
        const double dy = local.y - h * j, dyz2 = dy * dy + dz2;
        if (dyz2 >= r2) continue;
        const std::size_t row = sums.node(0, j, k);
        if (with_positions)
          add_to_row({sums.weight.data() + row, sums.offset_x.data() + row, sums.offset_y.data() + row,
                      sums.offset_z.data() + row, sums.radius.data() + row},
                     dx, dyz2, dy, dz, p.radius[i], inverse_r2);
        if (with_velocity)
          add_velocity_to_row(sums.velocity_x.data() + row, sums.velocity_y.data() + row,
                              sums.velocity_z.data() + row, dx, dyz2, p.velocity[i], inverse_r2);
      }
    }
  }
}

}  // namespace

BlockKernelSums gather_block_kernel_sums(Vec3d origin, int ny, int nz, double voxel_size, const LiquidParticles& p,
                                         const std::vector<std::uint32_t>& near, double kernel_radius) {
  BlockKernelSums sums;
  sums.ny = ny, sums.nz = nz;
  const std::size_t count = std::size_t(kFieldBlock) * ny * nz;
  for (auto* v : {&sums.weight, &sums.offset_x, &sums.offset_y, &sums.offset_z, &sums.radius}) v->assign(count, 0.0);
  gather_into(sums, origin, voxel_size, p, near, kernel_radius, true, false);
  return sums;
}

void add_block_velocity_sums(BlockKernelSums& sums, Vec3d origin, double voxel_size, const LiquidParticles& p,
                             const std::vector<std::uint32_t>& near, double kernel_radius) {
  if (p.velocity.empty() || !sums.velocity_x.empty()) return;
  for (auto* v : {&sums.velocity_x, &sums.velocity_y, &sums.velocity_z}) v->assign(sums.weight.size(), 0.0);
  gather_into(sums, origin, voxel_size, p, near, kernel_radius, false, true);
}

}  // namespace dp::mesh
