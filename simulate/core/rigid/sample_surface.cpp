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
    Vec3 a{positions[t[0]][0], positions[t[0]][1], positions[t[0]][2]};
    Vec3 b{positions[t[1]][0], positions[t[1]][1], positions[t[1]][2]};
    Vec3 c{positions[t[2]][0], positions[t[2]][1], positions[t[2]][2]};
    float longest = std::max({length(b - a), length(c - a), length(c - b)});
    int n = std::max(1, static_cast<int>(std::ceil(longest / spacing - 1e-4f)));
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        float u = static_cast<float>(i) / n, v = static_cast<float>(j) / n;
        Vec3 p = a + u * (b - a) + v * (c - a);
        std::array<std::int64_t, 3> key{std::llround(p.x / snap), std::llround(p.y / snap), std::llround(p.z / snap)};
        if (seen.insert(key).second) samples.push_back(p);
      }
  }
  return samples;
}

}  // namespace dp
