#pragma once
// Marching cubes over a sampled field (inside: value < 0) with vertices
// shared between cubes: every vertex sits on a grid edge and belongs to that
// edge, so the mesh is indexed, and closed wherever the field is positive on
// the grid's boundary.
#include "scalar_grid.h"
#include "surface_mesh.h"

namespace dp::mesh {

// Vertices lie where the linear interpolation of the field along the edge is
// zero; normals are the field's gradient (central differences at the edge's
// nodes, interpolated alike), normalized. The result depends only on the
// grid, not on thread count.
SurfaceMesh marching_cubes(const ScalarGrid& grid);

}  // namespace dp::mesh
