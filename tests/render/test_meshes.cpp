#include "test_meshes.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace dp::render::test {

namespace {

using V = std::array<float, 3>;

V sub(V a, V b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V cross(V a, V b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }
float dot(V a, V b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V unit(V a) {
  float l = std::sqrt(dot(a, a));
  return {a[0] / l, a[1] / l, a[2] / l};
}

// The icosahedron's vertices are the cyclic permutations of (0, +-1, +-phi);
// its faces are the vertex triples at mutual distance 2 (the edge length),
// which spares listing the 20 faces by hand.
void icosahedron(std::vector<V>& vertices, std::vector<std::array<std::uint32_t, 3>>& faces) {
  const float phi = (1 + std::sqrt(5.0f)) / 2;
  for (float a : {-1.0f, 1.0f})
    for (float b : {-phi, phi}) {
      vertices.push_back({0, a, b});
      vertices.push_back({a, b, 0});
      vertices.push_back({b, 0, a});
    }
  auto is_edge = [&](std::uint32_t i, std::uint32_t j) {
    V d = sub(vertices[i], vertices[j]);
    return std::abs(dot(d, d) - 4) < 1e-3f;
  };
  const auto n = static_cast<std::uint32_t>(vertices.size());
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = i + 1; j < n; ++j)
      for (std::uint32_t k = j + 1; k < n; ++k)
        if (is_edge(i, j) && is_edge(j, k) && is_edge(i, k)) faces.push_back({i, j, k});
}

// Every triangle split in four at its edge midpoints, shared between
// neighbours so the mesh stays closed.
void subdivide(std::vector<V>& vertices, std::vector<std::array<std::uint32_t, 3>>& faces) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoint_of;
  auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
    auto key = std::minmax(a, b);
    auto [it, inserted] = midpoint_of.try_emplace(key, static_cast<std::uint32_t>(vertices.size()));
    if (inserted) {
      V p = vertices[a], q = vertices[b];
      vertices.push_back({(p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2});
    }
    return it->second;
  };
  std::vector<std::array<std::uint32_t, 3>> finer;
  for (auto [a, b, c] : faces) {
    std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
    using Tri = std::array<std::uint32_t, 3>;
    finer.insert(finer.end(), {Tri{a, ab, ca}, Tri{b, bc, ab}, Tri{c, ca, bc}, Tri{ab, bc, ca}});
  }
  faces = std::move(finer);
}

}  // namespace

dp::io::TriangleMesh icosphere(std::array<float, 3> centre, float radius, int subdivisions) {
  std::vector<V> unit_vertices;
  std::vector<std::array<std::uint32_t, 3>> faces;
  icosahedron(unit_vertices, faces);
  for (int i = 0; i < subdivisions; ++i) subdivide(unit_vertices, faces);

  dp::io::TriangleMesh mesh;
  for (V& v : unit_vertices) {
    v = unit(v);
    mesh.normals.push_back(v);
    mesh.positions.push_back({centre[0] + radius * v[0], centre[1] + radius * v[1], centre[2] + radius * v[2]});
  }
  for (auto f : faces) {
    V a = unit_vertices[f[0]], b = unit_vertices[f[1]], c = unit_vertices[f[2]];
    if (dot(cross(sub(b, a), sub(c, a)), a) < 0) std::swap(f[1], f[2]);
    mesh.triangles.push_back(f);
  }
  return mesh;
}

dp::io::TriangleMesh box(std::array<float, 3> lo, std::array<float, 3> hi) {
  dp::io::TriangleMesh mesh;
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      V normal{0, 0, 0};
      normal[axis] = side ? 1.0f : -1.0f;
      const auto base = static_cast<std::uint32_t>(mesh.positions.size());
      for (int corner = 0; corner < 4; ++corner) {
        V p;
        p[axis] = side ? hi[axis] : lo[axis];
        p[u] = (corner == 1 || corner == 2) ? hi[u] : lo[u];
        p[v] = corner >= 2 ? hi[v] : lo[v];
        mesh.positions.push_back(p);
        mesh.normals.push_back(normal);
      }
      std::array<std::uint32_t, 3> first{base, base + 1, base + 2}, second{base, base + 2, base + 3};
      // (u, v) corners run counter-clockwise about +axis; the low side turns the other way.
      if (!side) {
        std::swap(first[1], first[2]);
        std::swap(second[1], second[2]);
      }
      mesh.triangles.push_back(first);
      mesh.triangles.push_back(second);
    }
  return mesh;
}

dp::io::PlyData liquid_ply(const dp::io::TriangleMesh& mesh) {
  dp::io::PlyData ply;
  ply.comments.push_back("dewpoint render test mesh");
  ply.vertex_count = mesh.positions.size();
  const char* names[] = {"x", "y", "z", "nx", "ny", "nz"};
  for (int k = 0; k < 6; ++k) {
    std::vector<double> column;
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
      column.push_back(k < 3 ? mesh.positions[i][k] : mesh.normals[i][k - 3]);
    ply.add(names[k], dp::io::PlyType::Float32, std::move(column));
  }
  ply.faces = mesh.triangles;
  return ply;
}

dp::io::TriangleMesh disk_facing_down(std::array<float, 3> c, float radius, int segments) {
  dp::io::TriangleMesh mesh;
  mesh.positions.push_back(c);
  for (int i = 0; i < segments; ++i) {
    const double a = 2 * 3.14159265358979 * i / segments;
    mesh.positions.push_back({c[0] + radius * static_cast<float>(std::cos(a)), c[1], c[2] + radius * static_cast<float>(std::sin(a))});
  }
  for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(segments); ++i)
    mesh.triangles.push_back({0, 1 + i, 1 + (i + 1) % static_cast<std::uint32_t>(segments)});
  mesh.normals.assign(mesh.positions.size(), {0, -1, 0});
  return mesh;
}

dp::io::TriangleMesh textured_square(float x0, float x1, float y0, float y1, float z0) {
  dp::io::TriangleMesh mesh;
  mesh.positions = {{x0, y0, z0}, {x1, y0, z0}, {x1, y1, z0}, {x0, y1, z0}};
  mesh.normals.assign(4, {0, 0, 1});
  mesh.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

dp::io::PlyData rigid_atlas_ply(const dp::io::TriangleMesh& mesh) {
  dp::io::PlyData ply = liquid_ply(mesh);
  std::vector<double> s, t;
  for (const auto& uv : mesh.uvs) s.push_back(uv[0]), t.push_back(uv[1]);
  ply.add("s", dp::io::PlyType::Float32, std::move(s));
  ply.add("t", dp::io::PlyType::Float32, std::move(t));
  return ply;
}

}  // namespace dp::render::test
