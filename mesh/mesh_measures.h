#pragma once
// Integral measures of a closed triangle mesh, recorded per frame so that a
// liquid's volume can be followed through a shot (evaporation shrinks it,
// condensation grows it).
#include "surface_mesh.h"

namespace dp::mesh {

// Signed volume enclosed (divergence theorem over the triangles); positive
// for a closed mesh with outward orientation.
double enclosed_volume(const SurfaceMesh& mesh);

double surface_area(const SurfaceMesh& mesh);

}  // namespace dp::mesh
