#include "grid_box.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace dp::mesh {

GridBox covering_grid(Vec3d lo, Vec3d hi, double voxel_size, double margin, std::int64_t max_nodes) {
  if (!(voxel_size > 0) || !std::isfinite(voxel_size))
    throw std::invalid_argument("voxel size must be positive and finite");
  GridBox box;
  box.voxel_size = voxel_size;
  double count = 1;
  for (int a = 0; a < 3; ++a) {
    const double first = std::floor((lo[a] - margin) / voxel_size);
    const double last = std::ceil((hi[a] + margin) / voxel_size);
    box.origin[a] = first * voxel_size;
    const double n = last - first + 1;
    count *= n;
    box.nodes[a] = n < 2e9 ? static_cast<int>(n) : 0;
  }
  if (!(count <= double(max_nodes)) || box.nodes[0] == 0 || box.nodes[1] == 0 || box.nodes[2] == 0) {
    char message[200];
    std::snprintf(message, sizeof message,
                  "a grid covering the particles at voxel size %g m would have %.3g nodes (limit %.3g); use a larger "
                  "--voxel-size",
                  voxel_size, count, double(max_nodes));
    throw std::runtime_error(message);
  }
  return box;
}

}  // namespace dp::mesh
