#pragma once
// The point of a triangle closest to a query point, by the Voronoi regions
// of its vertices, edges and face (Ericson, Real-Time Collision Detection,
// 2005, Sec. 5.1.5). Hand-written because Embree's point queries leave the
// per-primitive distance to the caller (its closest-point tutorial does the
// same).
#include "vec3d.h"

namespace dp::mesh {

Vec3d closest_point_on_triangle(Vec3d p, Vec3d a, Vec3d b, Vec3d c);

}  // namespace dp::mesh
