#pragma once
// dewpoint-mesh --check: what a renderer or a simulation reading the mesh
// relies on, checked with CGAL Polygon Mesh Processing rather than our own
// code, so the mesher is not its own judge.
#include <cstddef>

#include <nlohmann/json.hpp>

#include "surface_mesh.h"

namespace dp::mesh {

struct MeshCheck {
  bool manifold = false;   // every edge in two faces at most, every vertex one fan (no point had to be split)
  bool oriented = false;   // neighbouring faces agree: CGAL's orientation pass reversed none
  bool closed = false;     // no border edges
  bool outward = false;    // closed and oriented with normals out of the enclosed volume
  bool self_intersecting = true;
  std::size_t non_manifold_vertices = 0, reversed_faces = 0, border_edges = 0;
  double volume_m3 = 0, area_m2 = 0;

  bool passed() const { return manifold && oriented && closed && outward && !self_intersecting; }
};

MeshCheck check_mesh(const SurfaceMesh& mesh);

nlohmann::json to_json(const MeshCheck& check);

}  // namespace dp::mesh
