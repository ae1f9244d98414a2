#include "surface/seeding_points.h"

#include <limits>

#include "surface/point_hash_grid.h"

namespace dp {

SeedingPoints make_seeding_points(const TexelGeometry& texels, float spacing, std::uint32_t seed) {
  PoissonDiskSettings settings;
  settings.radius = spacing;
  settings.seed = seed;
  const std::vector<std::uint32_t> chosen = poisson_disk_samples(texels.position, texels.area, settings);

  SeedingPoints seeds;
  PointHashGrid grid(spacing);
  for (std::size_t s = 0; s < chosen.size(); ++s) {
    seeds.position.push_back(texels.position[chosen[s]]);
    seeds.normal.push_back(texels.normal[chosen[s]]);
    grid.insert(seeds.position.back(), static_cast<std::uint32_t>(s));
  }
  // Nearest seed per texel (the lower index on ties); texels of zero area
  // and none farther than the spacing belong to no seed.
  const std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> owner(texels.size(), none);
  std::vector<std::uint32_t> count(chosen.size() + 1, 0);
  for (std::size_t t = 0; t < texels.size(); ++t) {
    if (!(texels.area[t] > 0)) continue;
    float best = spacing * spacing;
    grid.for_each_near(texels.position[t], spacing, [&](std::uint32_t s) {
      const float d2 = length_squared(seeds.position[s] - texels.position[t]);
      if (d2 < best || (d2 == best && s < owner[t])) best = d2, owner[t] = s;
    });
    if (owner[t] != none) ++count[owner[t]];
  }
  seeds.texel_offset.assign(chosen.size() + 1, 0);
  for (std::size_t s = 0; s < chosen.size(); ++s) seeds.texel_offset[s + 1] = seeds.texel_offset[s] + count[s];
  seeds.texel_index.resize(seeds.texel_offset.back());
  std::vector<std::uint32_t> fill(seeds.texel_offset.begin(), seeds.texel_offset.end() - 1);
  for (std::size_t t = 0; t < texels.size(); ++t)
    if (owner[t] != none) seeds.texel_index[fill[owner[t]]++] = static_cast<std::uint32_t>(t);
  return seeds;
}

}  // namespace dp
