#pragma once
// Boundary particles on a rigid surface at the liquid's particle spacing
// (Akinci et al. 2012 sample rigid surfaces with one layer of particles).
#include <array>
#include <cstdint>
#include <vector>

#include "math/vec3.h"

namespace dp {

// Samples every triangle on a lattice along the two edges at the corner
// opposite its longest edge, with steps of at most `spacing`; points that coincide on shared edges and corners are
// kept once. Deterministic: the order follows the triangle list.
std::vector<Vec3> sample_surface(const std::vector<std::array<float, 3>>& positions,
                                 const std::vector<std::array<std::uint32_t, 3>>& triangles, float spacing);

}  // namespace dp
