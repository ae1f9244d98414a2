#include "liquid_field.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "block_kernel_sums.h"
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

double largest_radius(const LiquidParticles& p) {
  double r = 0;
  for (double ri : p.radius) r = std::max(r, ri);
  return r;
}

// The slabs holding every wall triangle within reach of some point of the
// box [lo, hi] (the xbars of a block's nodes), nearest to its centre first;
// empty when there are too many for the bound to pay.
std::vector<const WallSlab*> slabs_within_reach(Vec3d lo, Vec3d hi, const RigidWalls& walls, double reach) {
  constexpr std::size_t kMostSlabs = 32;
  const Vec3d centre = 0.5 * (lo + hi), half_extent = 0.5 * (hi - lo);
  reach *= 1 + 1e-6;  // the margin covers rounding
  std::vector<const WallSlab*> slabs;
  walls.slabs_near(centre, length(half_extent) + reach, slabs);
  std::erase_if(slabs, [&](const WallSlab* s) { return distance_to_slab(*s, centre, half_extent) >= reach; });
  if (slabs.size() > kMostSlabs) return {};
  std::sort(slabs.begin(), slabs.end(), [&](const WallSlab* a, const WallSlab* b) {
    return distance_to_slab(*a, centre) < distance_to_slab(*b, centre);
  });
  return slabs;
}

// Whether a wall can be within reach of xbar as far as the slabs tell: its
// triangles lie in them, and xbar is no closer to a triangle than to its slab.
bool slabs_allow_wall(const std::vector<const WallSlab*>& slabs, Vec3d xbar, double rbar,
                      const ContactAngleCorrection_HochstetterKolb2017& correction) {
  if (slabs.empty()) return true;  // no slab bound for this block
  for (const WallSlab* s : slabs)
    if (correction.wall_within_reach(distance_to_slab(*s, xbar), rbar)) return true;
  return false;
}

// A node whose xbar may have a wall within reach.
struct WallCandidate {
  Vec3d x;
  std::size_t local, node;
  LocalFluid fluid;
  double phi;  // uncorrected
};

struct WallNode {
  Vec3d x;
  std::size_t local, node;  // in the block's sums, in the grid
  WallPoint wall;           // xbar_p
};

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
      // The walls' distance from the block's centre, which bounds it at any xbar.
      const Vec3d centre = 0.5 * (b.lo + b.hi);
      WallPoint centre_wall;
      if (with_walls) {
        const double half_diagonal = 0.5 * length(b.hi - b.lo);
        centre_wall = correction->walls().closest(centre, half_diagonal + wall_reach);
        result.near_walls = centre_wall.found;
      }
      const int ny = b.nodes[1][1] - b.nodes[1][0], nz = b.nodes[2][1] - b.nodes[2][0];
      BlockKernelSums sums = gather_block_kernel_sums(b.lo, ny, nz, box.voxel_size, particles, near, kernel_radius);
      std::vector<WallCandidate> candidates;
      constexpr double kFar = std::numeric_limits<double>::infinity();
      Vec3d xbar_lo{kFar, kFar, kFar}, xbar_hi{-kFar, -kFar, -kFar};  // the candidates' xbars
      double largest_rbar = 0;
      for (int k = b.nodes[2][0]; k < b.nodes[2][1]; ++k)
        for (int j = b.nodes[1][0]; j < b.nodes[1][1]; ++j)
          for (int i = b.nodes[0][0]; i < b.nodes[0][1]; ++i) {
            const std::size_t local = sums.node(i - b.nodes[0][0], j - b.nodes[1][0], k - b.nodes[2][0]);
            const std::size_t node = static_cast<std::size_t>(box.node_index(i, j, k));
            const LocalFluid f = local_fluid(sums.at(local));
            const double phi = zhu_bridson_distance(f, kernel_radius);
            grid.values[node] = static_cast<float>(phi);
            if (!result.near_walls || !f.near_liquid || !correction->may_change_sign(phi, f.mean_radius)) continue;
            const Vec3d x = box.node_position(i, j, k);
            const Vec3d xbar = x + f.mean_offset;
            const double xbar_wall_gap = centre_wall.distance - length(xbar - centre);
            if (!correction->wall_within_reach(xbar_wall_gap, f.mean_radius)) continue;
            candidates.push_back({x, local, node, f, phi});
            for (int a = 0; a < 3; ++a) xbar_lo[a] = std::min(xbar_lo[a], xbar[a]), xbar_hi[a] = std::max(xbar_hi[a], xbar[a]);
            largest_rbar = std::max(largest_rbar, f.mean_radius);
          }
      if (candidates.empty()) return;
      // Nodes whose xbar has a wall within reach, corrected once the block
      // has its velocity sums: most blocks near walls have none.
      const std::vector<const WallSlab*> slabs =
          slabs_within_reach(xbar_lo, xbar_hi, correction->walls(), correction->fluid_reach(largest_rbar));
      std::vector<WallNode> wall_nodes;
      WallPoint last_wall = centre_wall;  // the next node's xbar_p most likely lies on the same triangle
      for (const WallCandidate& c : candidates) {
        if (!slabs_allow_wall(slabs, c.x + c.fluid.mean_offset, c.fluid.mean_radius, *correction)) continue;
        const WallPoint wall = correction->fluid_wall(c.x, c.fluid, c.phi, result.correction, last_wall);
        if (!wall.found) continue;
        wall_nodes.push_back({c.x, c.local, c.node, wall});
        last_wall = wall;
      }
      if (wall_nodes.empty()) return;
      add_block_velocity_sums(sums, b.lo, box.voxel_size, particles, near, kernel_radius);
      for (const WallNode& w : wall_nodes)
        grid.values[w.node] =
            static_cast<float>(correction->corrected_distance(w.x, local_fluid(sums.at(w.local)), w.wall, result.correction));
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
