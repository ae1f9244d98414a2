// Reading dewpoint-mesh's liquid surfaces.
#include <gtest/gtest.h>

#include <filesystem>
#include <unistd.h>

#include "liquid_mesh.h"
#include "ply.h"
#include "test_meshes.h"

namespace fs = std::filesystem;

namespace dp::render {
namespace {

fs::path temporary_ply(const std::string& name) {
  return fs::temp_directory_path() / ("dewpoint_render_" + std::to_string(::getpid()) + "_" + name + ".ply");
}

TEST(render_liquid_mesh, ReadsPositionsNormalsAndTriangles) {
  const dp::io::TriangleMesh written = test::icosphere({0, 0.1f, 0}, 0.1f, 1);
  const fs::path file = temporary_ply("roundtrip");
  dp::io::write_ply(file, test::liquid_ply(written));
  const dp::io::TriangleMesh read = load_liquid_mesh(file);
  fs::remove(file);
  EXPECT_EQ(read.positions, written.positions);
  EXPECT_EQ(read.normals, written.normals);
  EXPECT_EQ(read.triangles, written.triangles);
}

TEST(render_liquid_mesh, MissingNormalsAreAnErrorNamingFileAndProperty) {
  dp::io::PlyData ply;
  ply.vertex_count = 3;
  for (const char* axis : {"x", "y", "z"}) ply.add(axis, dp::io::PlyType::Float32, {0, 1, 0});
  ply.faces = {{0, 1, 2}};
  const fs::path file = temporary_ply("no_normals");
  dp::io::write_ply(file, ply);
  try {
    load_liquid_mesh(file);
    ADD_FAILURE() << "expected an error";
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(file.string()), std::string::npos) << message;
    EXPECT_NE(message.find("nx"), std::string::npos) << message;
  }
  fs::remove(file);
}

}  // namespace
}  // namespace dp::render
