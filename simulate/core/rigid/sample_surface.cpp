#include "rigid/sample_surface.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>

namespace dp {

namespace {
struct KeyHash {
  std::size_t operator()(const std::array<std::int64_t, 3>& k) const {
    return static_cast<std::size_t>(k[0] * 73856093LL ^ k[1] * 19349663LL ^ k[2] * 83492791LL);
  }
};
}  // namespace

std::vector<Vec3> sample_surface(const std::vector<std::array<float, 3>>& positions,
                                 const std::vector<std::array<std::uint32_t, 3>>& triangles, float spacing) {
  std::vector<Vec3> samples;
  std::unordered_set<std::array<std::int64_t, 3>, KeyHash> seen;
  // Points closer than a tenth of the spacing are the same lattice point seen
  // from two triangles.
  const double snap = 0.1 * spacing;
  for (const auto& t : triangles) {
    Vec3 v[3];
    for (int k = 0; k < 3; ++k) v[k] = Vec3{positions[t[k]][0], positions[t[k]][1], positions[t[k]][2]};
    // The lattice spans the two edges at the corner opposite the longest
    // edge: the two triangles of a rectangle then share one regular grid
    // at the spacing, instead of a lattice squeezed along the diagonal.
    int corner = 0;
    float longest = -1;
    for (int k = 0; k < 3; ++k) {
      float opposite = length(v[(k + 2) % 3] - v[(k + 1) % 3]);
      if (opposite > longest) longest = opposite, corner = k;
    }
    const Vec3 a = v[corner], e1 = v[(corner + 1) % 3] - a, e2 = v[(corner + 2) % 3] - a;
    const int n1 = std::max(1, static_cast<int>(std::ceil(length(e1) / spacing - 1e-4f)));
    const int n2 = std::max(1, static_cast<int>(std::ceil(length(e2) / spacing - 1e-4f)));
    for (int i = 0; i <= n1; ++i)
      for (int j = 0; j <= n2; ++j) {
        float u = static_cast<float>(i) / n1, w = static_cast<float>(j) / n2;
        if (u + w > 1.0f + 1e-5f) continue;
        Vec3 p = a + u * e1 + w * e2;
        std::array<std::int64_t, 3> key{std::llround(p.x / snap), std::llround(p.y / snap), std::llround(p.z / snap)};
        if (seen.insert(key).second) samples.push_back(p);
      }
  }
  return samples;
}

}  // namespace dp
