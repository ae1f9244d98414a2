#include "triangle_mesh.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <cmath>
#include <stdexcept>

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

TriangleMesh load_triangle_mesh(const std::filesystem::path& file) {
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
  if (mesh.triangles.empty()) throw std::runtime_error(file.string() + ": mesh has no triangles");
  if (!(mesh.area() > 0)) throw std::runtime_error(file.string() + ": mesh has zero surface area");
  return mesh;
}

}  // namespace dp::io
