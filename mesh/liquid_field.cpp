#include "liquid_field.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "particle_cell_grid.h"
#include "zhu_bridson.h"

namespace dp::mesh {

namespace {

using NodeRange = std::array<std::array<int, 2>, 3>;  // per axis: first node, one past the last

struct Block {
  NodeRange nodes;
  Vec3d lo, hi;  // the positions of its first and last nodes
};

Block block_at(const GridBox& box, int bi, int bj, int bk) {
  Block b;
  const int index[3] = {bi, bj, bk};
  for (int a = 0; a < 3; ++a) b.nodes[a] = {index[a] * kFieldBlock, std::min((index[a] + 1) * kFieldBlock, box.nodes[a])};
  b.lo = box.node_position(b.nodes[0][0], b.nodes[1][0], b.nodes[2][0]);
  b.hi = box.node_position(b.nodes[0][1] - 1, b.nodes[1][1] - 1, b.nodes[2][1] - 1);
  return b;
}

double distance_squared_to_box(Vec3d p, Vec3d lo, Vec3d hi) {
  double d2 = 0;
  for (int a = 0; a < 3; ++a) {
    const double d = std::max({lo[a] - p[a], 0.0, p[a] - hi[a]});
    d2 += d * d;
  }
  return d2;
}

// The particles within R of the block, in the cell grid's fixed order.
std::vector<std::uint32_t> particles_near(const Block& b, const ParticleCellGrid& cells, const LiquidParticles& p,
                                          double kernel_radius) {
  std::vector<std::uint32_t> near;
  const Vec3d reach{kernel_radius, kernel_radius, kernel_radius};
  const double r2 = kernel_radius * kernel_radius;
  cells.for_each_in_box(b.lo - reach, b.hi + reach, [&](std::uint32_t i) {
    if (distance_squared_to_box(p.position[i], b.lo, b.hi) < r2) near.push_back(i);
  });
  return near;
}

// Kernel sums at every node of the block, particle by particle.
std::vector<KernelSums> gather_kernel_sums(const Block& b, const GridBox& box, const LiquidParticles& p,
                                           const std::vector<std::uint32_t>& near, double kernel_radius) {
  const int nx = b.nodes[0][1] - b.nodes[0][0], ny = b.nodes[1][1] - b.nodes[1][0], nz = b.nodes[2][1] - b.nodes[2][0];
  std::vector<KernelSums> sums(std::size_t(nx) * ny * nz);
  const double h = box.voxel_size, r2 = kernel_radius * kernel_radius, inverse_r2 = 1 / r2;
  const bool moving = !p.velocity.empty();
  for (std::uint32_t i : near) {
    // In block coordinates (node units from the block's first node), so
    // that offsets do not cancel large world coordinates.
    const Vec3d local = p.position[i] - b.lo;
    int first[3], last[3];
    const int extent[3] = {nx, ny, nz};
    for (int a = 0; a < 3; ++a) {
      first[a] = std::max(0, int(std::ceil((local[a] - kernel_radius) / h)));
      last[a] = std::min(extent[a] - 1, int(std::floor((local[a] + kernel_radius) / h)));
    }
    const Vec3d v = moving ? p.velocity[i] : Vec3d{};
    for (int k = first[2]; k <= last[2]; ++k)
      for (int j = first[1]; j <= last[1]; ++j)
        for (int n = first[0]; n <= last[0]; ++n) {
          const Vec3d offset = local - h * Vec3d{double(n), double(j), double(k)};  // x_i - x
          const double d2 = length_squared(offset);
          if (d2 >= r2) continue;
          sums[(std::size_t(k) * ny + j) * nx + n].add(zhu_bridson_kernel(d2 * inverse_r2), offset, p.radius[i], v);
        }
  }
  return sums;
}

double largest_radius(const LiquidParticles& p) {
  double r = 0;
  for (double ri : p.radius) r = std::max(r, ri);
  return r;
}

struct BlockResult {
  bool active = false, near_walls = false;
  CorrectionCounts correction;
};

}  // namespace

ScalarGrid sample_liquid_field(const LiquidParticles& particles, double kernel_radius, const GridBox& box,
                               const ContactAngleCorrection_HochstetterKolb2017* correction,
                               LiquidFieldCounts* counts) {
  ScalarGrid grid;
  grid.box = box;
  grid.values.assign(static_cast<std::size_t>(box.node_count()), static_cast<float>(kernel_radius));
  int blocks[3];
  for (int a = 0; a < 3; ++a) blocks[a] = (box.nodes[a] + kFieldBlock - 1) / kFieldBlock;
  const std::size_t block_count = std::size_t(blocks[0]) * blocks[1] * blocks[2];
  std::vector<BlockResult> results(block_count);
  if (particles.size() > 0) {
    const ParticleCellGrid cells(particles.position, kernel_radius);
    const bool with_walls = correction && !correction->walls().empty();
    const double wall_reach = with_walls ? correction->wall_reach(kernel_radius, largest_radius(particles)) : 0;

    tbb::parallel_for(std::size_t{0}, block_count, [&](std::size_t index) {
      const int bi = int(index % blocks[0]), bj = int(index / blocks[0] % blocks[1]), bk = int(index / blocks[0] / blocks[1]);
      const Block b = block_at(box, bi, bj, bk);
      const std::vector<std::uint32_t> near = particles_near(b, cells, particles, kernel_radius);
      if (near.empty()) return;
      BlockResult& result = results[index];
      result.active = true;
      const std::vector<KernelSums> sums = gather_kernel_sums(b, box, particles, near, kernel_radius);
      if (with_walls) {
        const Vec3d centre = 0.5 * (b.lo + b.hi);
        result.near_walls = correction->walls().closest(centre, 0.5 * length(b.hi - b.lo) + wall_reach).found;
      }
      const int nx = b.nodes[0][1] - b.nodes[0][0], ny = b.nodes[1][1] - b.nodes[1][0];
      for (int k = b.nodes[2][0]; k < b.nodes[2][1]; ++k)
        for (int j = b.nodes[1][0]; j < b.nodes[1][1]; ++j)
          for (int i = b.nodes[0][0]; i < b.nodes[0][1]; ++i) {
            const std::size_t local = (std::size_t(k - b.nodes[2][0]) * ny + (j - b.nodes[1][0])) * nx + (i - b.nodes[0][0]);
            const LocalFluid f = local_fluid(sums[local]);
            double phi = zhu_bridson_distance(f, kernel_radius);
            if (result.near_walls) phi = correction->distance(box.node_position(i, j, k), f, phi, result.correction);
            grid.values[static_cast<std::size_t>(box.node_index(i, j, k))] = static_cast<float>(phi);
          }
    });
  }
  if (counts) {
    *counts = {};
    counts->blocks = block_count;
    for (const BlockResult& r : results) {
      counts->active_blocks += r.active;
      counts->blocks_near_walls += r.near_walls;
      counts->correction += r.correction;
    }
  }
  return grid;
}

}  // namespace dp::mesh
