#include "mesh_ply.h"

#include <stdexcept>
#include <string>

namespace dp::mesh {

namespace {

std::vector<double> component(const std::vector<Vec3d>& v, int axis) {
  std::vector<double> c(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) c[i] = v[i][axis];
  return c;
}

}  // namespace

io::PlyData mesh_to_ply(const SurfaceMesh& mesh, const std::string& comment) {
  if (mesh.normal.size() != mesh.position.size())
    throw std::logic_error("mesh has " + std::to_string(mesh.normal.size()) + " normals for " +
                           std::to_string(mesh.position.size()) + " vertices");
  io::PlyData ply;
  ply.comments.push_back(comment);
  ply.vertex_count = mesh.position.size();
  const char* position_name[3] = {"x", "y", "z"};
  const char* normal_name[3] = {"nx", "ny", "nz"};
  for (int a = 0; a < 3; ++a) ply.add(position_name[a], io::PlyType::Float32, component(mesh.position, a));
  for (int a = 0; a < 3; ++a) ply.add(normal_name[a], io::PlyType::Float32, component(mesh.normal, a));
  ply.faces = mesh.triangles;
  return ply;
}

void write_mesh_ply(const std::filesystem::path& file, const SurfaceMesh& mesh, const std::string& comment) {
  io::write_ply(file, mesh_to_ply(mesh, comment));
}

}  // namespace dp::mesh
