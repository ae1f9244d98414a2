#pragma once
// Points, directions and normals in metres, world space: the simulator
// core's single-precision Vec3, which is also what Embree intersects with.
#include "math/vec3.h"

namespace dp::render {
using dp::Vec3;
}  // namespace dp::render
