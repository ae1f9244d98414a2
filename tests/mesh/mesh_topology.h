#pragma once
// Combinatorial checks of a triangle mesh, written for the tests and
// independent of how the mesher builds its meshes.
#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <utility>

#include "surface_mesh.h"

namespace dp::mesh::testing {

// Empty when every directed edge occurs exactly once and its reverse occurs
// too: then every edge has exactly two triangles, which agree on
// orientation. Otherwise the first problem found.
inline std::string orientation_problem(const SurfaceMesh& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const auto& t : mesh.triangles) {
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) return "a triangle repeats a vertex";
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  }
  for (const auto& [edge, count] : directed) {
    const std::string name = std::to_string(edge.first) + "->" + std::to_string(edge.second);
    if (count != 1) return "directed edge " + name + " occurs " + std::to_string(count) + " times";
    if (!directed.count({edge.second, edge.first})) return "directed edge " + name + " has no reverse (open boundary)";
  }
  return "";
}

inline long euler_characteristic(const SurfaceMesh& mesh) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
  return long(mesh.position.size()) - long(edges.size()) + long(mesh.triangles.size());
}

}  // namespace dp::mesh::testing
