#include "triangle_mesh.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

namespace dp::io {

double TriangleMesh::area() const {
  double total = 0;
  for (const auto& t : triangles) {
    const auto &a = positions[t[0]], &b = positions[t[1]], &c = positions[t[2]];
    double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    double cx = u[1] * v[2] - u[2] * v[1], cy = u[2] * v[0] - u[0] * v[2], cz = u[0] * v[1] - u[1] * v[0];
    total += 0.5 * std::sqrt(cx * cx + cy * cy + cz * cz);
  }
  return total;
}

namespace {

// Vertices welded by position: files split a vertex wherever its normal or
// UV changes, which must not make a closed surface look cut open.
std::vector<std::uint32_t> welded_vertices(const TriangleMesh& mesh) {
  std::map<std::array<float, 3>, std::uint32_t> first;
  std::vector<std::uint32_t> id(mesh.positions.size());
  for (std::size_t v = 0; v < mesh.positions.size(); ++v)
    id[v] = first.emplace(mesh.positions[v], static_cast<std::uint32_t>(first.size())).first->second;
  return id;
}

}  // namespace

std::string first_non_manifold_edge(const TriangleMesh& mesh) {
  const std::vector<std::uint32_t> id = welded_vertices(mesh);
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> faces_of_edge;
  for (const auto& t : mesh.triangles)
    for (int e = 0; e < 3; ++e) {
      std::uint32_t a = id[t[e]], b = id[t[(e + 1) % 3]];
      if (a == b) continue;  // a collapsed edge bounds nothing
      if (a > b) std::swap(a, b);
      ++faces_of_edge[{a, b}];
    }
  for (const auto& t : mesh.triangles)
    for (int e = 0; e < 3; ++e) {
      std::uint32_t a = id[t[e]], b = id[t[(e + 1) % 3]];
      if (a > b) std::swap(a, b);
      const auto it = faces_of_edge.find({a, b});
      if (it == faces_of_edge.end() || it->second <= 2) continue;
      const auto &p = mesh.positions[t[e]], &q = mesh.positions[t[(e + 1) % 3]];
      return "the edge from (" + std::to_string(p[0]) + ", " + std::to_string(p[1]) + ", " + std::to_string(p[2]) + ") to (" +
             std::to_string(q[0]) + ", " + std::to_string(q[1]) + ", " + std::to_string(q[2]) + ") is shared by " +
             std::to_string(it->second) + " triangles";
    }
  return {};
}

TriangleMesh load_triangle_mesh(const std::filesystem::path& file) {
  // assimp reports a folder as an unknown format; say what it is.
  if (std::filesystem::is_directory(file)) throw std::runtime_error(file.string() + ": cannot load mesh: is a directory");
  Assimp::Importer importer;
  // Pre-transforming bakes the node hierarchy into world space, so the mesh
  // is where the scene file's author placed it.
  const aiScene* scene = importer.ReadFile(file.string(), aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                                              aiProcess_PreTransformVertices | aiProcess_GenSmoothNormals |
                                                              aiProcess_SortByPType);
  if (!scene) throw std::runtime_error(file.string() + ": cannot load mesh: " + importer.GetErrorString());

  TriangleMesh mesh;
  bool all_have_uvs = true;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) all_have_uvs = all_have_uvs && scene->mMeshes[m]->HasTextureCoords(0);
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* am = scene->mMeshes[m];
    if (!(am->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
    auto base = static_cast<std::uint32_t>(mesh.positions.size());
    for (unsigned v = 0; v < am->mNumVertices; ++v) {
      mesh.positions.push_back({am->mVertices[v].x, am->mVertices[v].y, am->mVertices[v].z});
      mesh.normals.push_back({am->mNormals[v].x, am->mNormals[v].y, am->mNormals[v].z});
      if (all_have_uvs) mesh.uvs.push_back({am->mTextureCoords[0][v].x, am->mTextureCoords[0][v].y});
    }
    for (unsigned f = 0; f < am->mNumFaces; ++f) {
      const aiFace& face = am->mFaces[f];
      if (face.mNumIndices != 3) continue;
      mesh.triangles.push_back({base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]});
    }
  }
  if (mesh.triangles.empty()) throw std::runtime_error(file.string() + ": expected a mesh with triangles, found none");
  if (!(mesh.area() > 0))
    throw std::runtime_error(file.string() + ": expected a mesh with a positive surface area, found " + std::to_string(mesh.area()) +
                             " m^2 (all " + std::to_string(mesh.triangles.size()) + " triangles are degenerate)");
  // Boundary particles sample a surface with an inside and an outside; an
  // edge between three or more triangles has neither (open edges, with one
  // triangle, are fine: a tray or a sheet).
  if (const std::string edge = first_non_manifold_edge(mesh); !edge.empty())
    throw std::runtime_error(file.string() + ": mesh is not manifold: " + edge);
  return mesh;
}

}  // namespace dp::io
