#include "sph/pcisph_solenthaler2009.h"

#include <cmath>

namespace dp {

float pcisph_prototype_sum(const CubicSplineKernel& kernel, float spacing) {
  // Neighbours on the cubic lattice around a particle at the origin.
  const int reach = static_cast<int>(std::ceil(kernel.h / spacing));
  Vec3 sum_grad{};
  double sum_sq = 0.0;
  for (int k = -reach; k <= reach; ++k)
    for (int j = -reach; j <= reach; ++j)
      for (int i = -reach; i <= reach; ++i) {
        if (i == 0 && j == 0 && k == 0) continue;
        Vec3 xij = Vec3{0, 0, 0} - Vec3{i * spacing, j * spacing, k * spacing};
        Vec3 g = kernel.gradW(xij);
        sum_grad += g;
        sum_sq += dot(g, g);
      }
  return static_cast<float>(dot(sum_grad, sum_grad) + sum_sq);
}

}  // namespace dp
