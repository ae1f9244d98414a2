#pragma once
// Static particle sets sorted into the neighbour grid, for tests that call
// the core's functors directly: the physics runs on the sorted order, the
// checks read results back in lattice order.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "backend/cpu_exec.h"
#include "sph/particle_grid.h"

namespace dp::test {

struct SortedSet {
  ParticleGrid<CpuExec> grid;
  std::vector<Vec3> position;  // sorted

  GridView view() const { return grid.view(position); }
  std::size_t size() const { return position.size(); }

  template <class T>
  std::vector<T> to_sorted(const std::vector<T>& v) const {
    std::vector<T> out(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) out[i] = v[grid.order[i]];
    return out;
  }
  template <class T>
  std::vector<T> to_lattice(const std::vector<T>& v) const {
    std::vector<T> out(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) out[grid.order[i]] = v[i];
    return out;
  }
};

// A grid of cell size h over the bounding box of all sets, so that every
// set's view can be queried at every other set's positions.
inline UniformGrid grid_around(const std::vector<std::vector<Vec3>>& sets, float h) {
  Vec3 lo{1e30f, 1e30f, 1e30f}, hi{-1e30f, -1e30f, -1e30f};
  for (const auto& set : sets)
    for (Vec3 p : set) {
      lo = Vec3{std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = Vec3{std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
  UniformGrid g;
  g.origin = lo - Vec3{h, h, h};
  g.cell_size = h;
  g.nx = static_cast<int>(std::ceil((hi.x - lo.x) / h)) + 3;
  g.ny = static_cast<int>(std::ceil((hi.y - lo.y) / h)) + 3;
  g.nz = static_cast<int>(std::ceil((hi.z - lo.z) / h)) + 3;
  return g;
}

inline SortedSet sort_into(const CpuExec& exec, const std::vector<Vec3>& position, const UniformGrid& grid) {
  SortedSet s;
  s.grid.grid = grid;
  CpuExec::Buffer<Vec3> unsorted = position;
  s.position.resize(position.size());
  s.grid.sort(exec, unsorted);
  exec.parallel_for(position.size(), Gather<Vec3>{s.grid.order.data(), unsorted.data(), s.position.data()});
  s.grid.find_ranges(exec);
  return s;
}

// nx x ny x nz lattice points at `spacing`, the first at `corner`, x fastest.
inline std::vector<Vec3> lattice_block(Vec3 corner, int nx, int ny, int nz, float spacing) {
  std::vector<Vec3> p;
  p.reserve(static_cast<std::size_t>(nx) * ny * nz);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) p.push_back(corner + spacing * Vec3{float(i), float(j), float(k)});
  return p;
}

}  // namespace dp::test
