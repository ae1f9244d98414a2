#include "liquid_mesh.h"

#include <stdexcept>

#include "ply.h"

namespace dp::render {

namespace {

std::vector<std::array<float, 3>> vectors(const dp::io::PlyData& ply, const char* x, const char* y, const char* z) {
  const std::vector<float> xs = ply.floats(x), ys = ply.floats(y), zs = ply.floats(z);
  std::vector<std::array<float, 3>> v(ply.vertex_count);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = {xs[i], ys[i], zs[i]};
  return v;
}

}  // namespace

dp::io::TriangleMesh load_liquid_mesh(const std::filesystem::path& file) {
  if (!std::filesystem::exists(file)) throw std::runtime_error(file.string() + ": liquid mesh not found (has dewpoint-mesh run for this frame?)");
  const dp::io::PlyData ply = dp::io::read_ply(file);
  dp::io::TriangleMesh mesh;
  try {
    mesh.positions = vectors(ply, "x", "y", "z");
    mesh.normals = vectors(ply, "nx", "ny", "nz");
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(file.string() + ": " + e.what());
  }
  mesh.triangles = ply.faces;
  return mesh;
}

}  // namespace dp::render
