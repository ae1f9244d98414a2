#pragma once
// A scalar field sampled at the nodes of a GridBox. Inside is negative.
#include <vector>

#include "grid_box.h"

namespace dp::mesh {

struct ScalarGrid {
  GridBox box;
  // float halves the memory of the largest buffer; the field is smooth at
  // voxel scale, so float's 7 digits are far below the interpolation error.
  std::vector<float> values;

  float at(int i, int j, int k) const { return values[static_cast<std::size_t>(box.node_index(i, j, k))]; }
};

}  // namespace dp::mesh
