#include "mesh_measures.h"

namespace dp::mesh {

double enclosed_volume(const SurfaceMesh& mesh) {
  // Tetrahedra against a point of the mesh rather than the origin: the same
  // sum for a closed mesh, with less cancellation far from the origin.
  if (mesh.position.empty()) return 0;
  const Vec3d apex = mesh.position[0];
  double six_volume = 0;
  for (const auto& t : mesh.triangles)
    six_volume += dot(mesh.position[t[0]] - apex, cross(mesh.position[t[1]] - apex, mesh.position[t[2]] - apex));
  return six_volume / 6;
}

double surface_area(const SurfaceMesh& mesh) {
  double twice_area = 0;
  for (const auto& t : mesh.triangles)
    twice_area += length(cross(mesh.position[t[1]] - mesh.position[t[0]], mesh.position[t[2]] - mesh.position[t[0]]));
  return twice_area / 2;
}

}  // namespace dp::mesh
