#pragma once
// Particle seeding positions on a rigid's surface (paper Sec. 4.3): Poisson-
// disk samples at the liquid particle spacing, so that particles emitted from
// neighbouring seeds (Sec. 6.2) never start closer than one spacing. Each
// texel belongs to its nearest seed; as the samples are maximal, that seed
// lies within one spacing, and every texel feeds exactly one seed.
#include "surface/poisson_disk_bridson2007.h"
#include "surface/surface_texture_setup.h"

namespace dp {

SeedingPoints make_seeding_points(const TexelGeometry& texels, float spacing, std::uint32_t seed = 2007);

}  // namespace dp
