#pragma once
// Fills a grid from a field function, in parallel over z-slabs. Every node
// is computed on its own from its position, so the result is the same for
// any number of threads (and any scheduling).
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "scalar_grid.h"

namespace dp::mesh {

// field(Vec3d position) -> double.
template <class Field>
ScalarGrid sample_grid(const GridBox& box, const Field& field) {
  ScalarGrid grid;
  grid.box = box;
  grid.values.resize(static_cast<std::size_t>(box.node_count()));
  tbb::parallel_for(tbb::blocked_range<int>(0, box.nodes[2]), [&](const tbb::blocked_range<int>& slabs) {
    for (int k = slabs.begin(); k != slabs.end(); ++k)
      for (int j = 0; j < box.nodes[1]; ++j)
        for (int i = 0; i < box.nodes[0]; ++i)
          grid.values[static_cast<std::size_t>(box.node_index(i, j, k))] =
              static_cast<float>(field(box.node_position(i, j, k)));
  });
  return grid;
}

}  // namespace dp::mesh
