#include "mesh_check.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <array>
#include <vector>

namespace dp::mesh {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using CgalMesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;

}  // namespace

MeshCheck check_mesh(const SurfaceMesh& mesh) {
  MeshCheck check;
  check.self_intersecting = false;
  if (mesh.triangles.empty()) {
    check.manifold = check.oriented = check.closed = check.outward = true;
    return check;
  }
  std::vector<Point> points;
  points.reserve(mesh.position.size());
  for (const Vec3d& p : mesh.position) points.emplace_back(p.x, p.y, p.z);
  std::vector<std::array<std::size_t, 3>> faces;
  faces.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) faces.push_back({t[0], t[1], t[2]});
  const std::vector<std::array<std::size_t, 3>> as_written = faces;

  // Orienting the soup splits points where the surface is not a manifold
  // and reverses faces that disagree with their neighbours; both are
  // failures of the mesher, counted here.
  const std::size_t points_before = points.size();
  PMP::orient_polygon_soup(points, faces);
  check.non_manifold_vertices = points.size() - points_before;
  for (std::size_t f = 0; f < faces.size(); ++f)
    if (faces[f] != as_written[f]) ++check.reversed_faces;
  check.manifold = check.non_manifold_vertices == 0;
  check.oriented = check.reversed_faces == 0;

  CgalMesh cgal;
  PMP::polygon_soup_to_polygon_mesh(points, faces, cgal);
  for (auto h : cgal.halfedges())
    if (cgal.is_border(h)) ++check.border_edges;
  check.closed = CGAL::is_closed(cgal);
  check.outward = check.closed && check.oriented && PMP::is_outward_oriented(cgal);
  check.self_intersecting = PMP::does_self_intersect(cgal);
  check.area_m2 = PMP::area(cgal);
  if (check.closed) check.volume_m3 = PMP::volume(cgal);
  return check;
}

nlohmann::json to_json(const MeshCheck& c) {
  return {{"passed", c.passed()},
          {"manifold", c.manifold},
          {"oriented", c.oriented},
          {"closed", c.closed},
          {"outward", c.outward},
          {"self_intersecting", c.self_intersecting},
          {"non_manifold_vertices", c.non_manifold_vertices},
          {"reversed_faces", c.reversed_faces},
          {"border_edges", c.border_edges},
          {"volume_m3", c.volume_m3},
          {"area_m2", c.area_m2}};
}

}  // namespace dp::mesh
