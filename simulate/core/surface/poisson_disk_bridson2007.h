#pragma once
// Poisson-disk sampling after Bridson 2007, "Fast Poisson Disk Sampling in
// Arbitrary Dimensions" (SIGGRAPH sketches), on a surface given by its
// texels (paper Sec. 4.3: particle seeding positions). Bridson draws
// candidates uniformly from the annulus [r, 2r) around an active sample and
// keeps one when no sample lies closer than r; on a surface the annulus is
// the part of the surface in the spherical shell, represented by the texels
// in it, drawn with probability proportional to their area (an active
// sample that succeeds tries again before another is drawn). Bridson's active
// list only grows within reach of the first sample, so disconnected parts of
// the surface get a new start; a final sweep over all texels makes the set
// maximal at texel resolution: every texel lies within r of a sample.
#include <cstdint>
#include <vector>

#include "math/vec3.h"

namespace dp {

struct PoissonDiskSettings {
  float radius = 0.01f;       // r: minimum distance between samples (m)
  int attempts = 30;          // Bridson's k
  std::uint32_t seed = 2007;  // random stream; the result is a function of it and the texels
};

// Indices of the texels chosen as samples, in the order they were chosen.
std::vector<std::uint32_t> poisson_disk_samples(const std::vector<Vec3>& position, const std::vector<float>& area,
                                                const PoissonDiskSettings& settings);

}  // namespace dp
