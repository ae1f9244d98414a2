#include "particle_cell_grid.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace dp::mesh {

ParticleCellGrid::ParticleCellGrid(const std::vector<Vec3d>& position, double cell_size)
    : position_(position), cell_size_(cell_size) {
  if (!(cell_size > 0)) throw std::invalid_argument("particle cell size must be positive");
  if (position.empty()) return;
  if (position.size() >= UINT32_MAX) throw std::runtime_error("too many particles for one frame (2^32)");
  Vec3d lo = position[0], hi = position[0];
  for (const Vec3d& x : position)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], x[a]);
      hi[a] = std::max(hi[a], x[a]);
    }
  origin_ = lo;
  double total = 1;
  for (int a = 0; a < 3; ++a) total *= std::floor((hi[a] - lo[a]) / cell_size) + 1;
  // Cells are far coarser than voxels, so any sampling grid that fits in
  // memory has a cell grid that fits; this only stops absurd spreads.
  if (!(total <= double(std::int64_t{1} << 28))) {
    char message[120];
    std::snprintf(message, sizeof message, "particles spread over %.3g neighbour cells (limit 2^28)", total);
    throw std::runtime_error(message);
  }
  for (int a = 0; a < 3; ++a) cells_[a] = static_cast<std::int64_t>(std::floor((hi[a] - lo[a]) / cell_size)) + 1;
  std::vector<std::uint32_t> count(static_cast<std::size_t>(total) + 1, 0);
  std::vector<std::int64_t> cell(position.size());
  for (std::size_t p = 0; p < position.size(); ++p) {
    const auto c = cell_of(position[p]);
    cell[p] = (c[2] * cells_[1] + c[1]) * cells_[0] + c[0];
    ++count[static_cast<std::size_t>(cell[p]) + 1];
  }
  cell_start_.assign(count.size(), 0);
  for (std::size_t c = 1; c < count.size(); ++c) cell_start_[c] = cell_start_[c - 1] + count[c];
  sorted_.resize(position.size());
  std::vector<std::uint32_t> next(cell_start_.begin(), cell_start_.end() - 1);
  for (std::size_t p = 0; p < position.size(); ++p) sorted_[next[static_cast<std::size_t>(cell[p])]++] = std::uint32_t(p);
}

std::array<std::int64_t, 3> ParticleCellGrid::cell_of(Vec3d x) const {
  std::array<std::int64_t, 3> c;
  for (int a = 0; a < 3; ++a) {
    const double f = std::floor((x[a] - origin_[a]) / cell_size_);
    // Far-away query points clamp to just outside the grid; clamping keeps
    // them out of int64 overflow and still finds no cells within reach.
    c[a] = static_cast<std::int64_t>(std::clamp(f, -2.0, double(cells_[a] + 1)));
  }
  return c;
}

}  // namespace dp::mesh
