// The rigid-surface files of the frames folder (docs/file-formats.md), read
// back through OpenImageIO's EXR reader and the PLY reader: channel names,
// orientation (row 0 at the top), zeros outside the charts, atomic writing.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include "frames.h"
#include "ply.h"
#include "surface_frames.h"
#include "surface_test_meshes.h"
#include "triangle_mesh.h"

namespace fs = std::filesystem;

namespace dp::io {
namespace {

SurfaceSnapshot small_snapshot() {
  SurfaceSnapshot s;
  s.width = 8;
  s.height = 4;
  s.kg_per_unit = 1e-20;
  // Three texels: top-left, (row 1, col 5), bottom-right.
  s.pixel = {0, 1 * 8 + 5, 3 * 8 + 7};
  s.mass_units = {TexelMassUnits{1} << 40, 12345678901234ull, 0};
  s.max_mass = {1e-6f, 2e-6f, 3e-6f};
  s.temperature = {277.15f, 293.15f, 423.15f};
  s.wetting = {1.0f, 0.25f, 0.0f};
  return s;
}

TEST(SurfaceFrames, ExrHasTheFourNamedChannelsWithRowZeroAtTheTop) {
  const fs::path dir = test::test_dir("exr");
  for (auto& entry : fs::directory_iterator(dir)) fs::remove(entry.path());
  const fs::path file = dir / frame_file_name("surface_mirror", 3, "exr");
  EXPECT_EQ(file.filename(), "surface_mirror.0003.exr");
  const SurfaceSnapshot s = small_snapshot();
  write_surface_frame(file, s);

  auto in = OIIO::ImageInput::open(file.string());
  ASSERT_TRUE(in) << OIIO::geterror();
  const OIIO::ImageSpec& spec = in->spec();
  EXPECT_EQ(in->format_name(), std::string("openexr"));
  ASSERT_EQ(spec.width, 8);
  ASSERT_EQ(spec.height, 4);
  ASSERT_EQ(spec.nchannels, 4);
  EXPECT_EQ(spec.channelnames, (std::vector<std::string>{"mass", "max_mass", "temperature", "wetting"}));
  EXPECT_EQ(spec.format, OIIO::TypeDesc::FLOAT);
  std::vector<float> pixels(8 * 4 * 4);
  ASSERT_TRUE(in->read_image(0, 0, 0, 4, OIIO::TypeDesc::FLOAT, pixels.data()));
  in->close();
  for (int p = 0; p < 32; ++p) {
    const float* v = &pixels[p * 4];
    std::size_t k = 0;
    while (k < s.pixel.size() && s.pixel[k] != static_cast<std::uint32_t>(p)) ++k;
    if (k == s.pixel.size()) {
      for (int c = 0; c < 4; ++c) EXPECT_EQ(v[c], 0.0f) << "pixel " << p << " outside every chart";
      continue;
    }
    EXPECT_FLOAT_EQ(v[0], static_cast<float>(static_cast<double>(s.mass_units[k]) * s.kg_per_unit));
    EXPECT_EQ(v[1], s.max_mass[k]);
    EXPECT_EQ(v[2], s.temperature[k]);
    EXPECT_EQ(v[3], s.wetting[k]);
  }
  // The pixel read first (OpenImageIO's row 0, the top) is texel row 0.
  EXPECT_EQ(pixels[2], 277.15f);
  for (auto& entry : fs::directory_iterator(dir)) EXPECT_EQ(entry.path().extension(), ".exr") << entry.path();
}

TEST(SurfaceFrames, RigidMeshPlyCarriesPositionsNormalsAndAtlasUvs) {
  TriangleMesh mesh = load_triangle_mesh(test::plane_with_uvs("ply", 0.3f, 0.2f, 3, 0.1f, 0.9f));
  AtlasMesh atlas = make_surface_atlas(mesh, 64, 64, "ply");
  const fs::path file = test::test_dir("ply") / "rigid_plate.ply";
  write_rigid_atlas_mesh(file, atlas, "test");
  PlyData ply = read_ply(file);
  ASSERT_EQ(ply.vertex_count, atlas.positions.size());
  ASSERT_EQ(ply.faces.size(), atlas.triangles.size());
  std::vector<std::string> names;
  for (const auto& p : ply.vertex) names.push_back(p.name);
  EXPECT_EQ(names, (std::vector<std::string>{"x", "y", "z", "nx", "ny", "nz", "s", "t"}));
  for (const auto& p : ply.vertex) EXPECT_EQ(p.type, PlyType::Float32);
  const std::vector<float> s = ply.floats("s"), t = ply.floats("t");
  for (std::size_t i = 0; i < s.size(); ++i) {
    EXPECT_FLOAT_EQ(s[i], atlas.uvs[i][0]);
    EXPECT_FLOAT_EQ(t[i], atlas.uvs[i][1]);
  }
}

TEST(SurfaceFrames, ManifestListsRigidsAndSurfaceFilesAndReadsThemBack) {
  const fs::path dir = test::test_dir("manifest");
  FramesManifest m;
  m.scene_file = "/x/scene.json";
  m.scene_name = "shot";
  m.rigid_particles_file = "rigid_particles.ply";
  m.rigids.push_back({"mirror", "rigid_mirror.ply", {512, 256}});
  FrameEntry e;
  e.particles_file = "particles.0000.ply";
  e.surface_files["mirror"] = "surface_mirror.0000.exr";
  m.frames.push_back(e);
  write_manifest(dir, m);
  std::ifstream in(dir / "manifest.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["rigids"][0]["name"], "mirror");
  EXPECT_EQ(j["rigids"][0]["mesh"], "rigid_mirror.ply");
  EXPECT_EQ(j["rigids"][0]["texture_resolution"], nlohmann::json::array({512, 256}));
  EXPECT_EQ(j["frames"][0]["files"]["surfaces"]["mirror"], "surface_mirror.0000.exr");
  const FramesManifest back = read_manifest(dir);
  ASSERT_EQ(back.rigids.size(), 1u);
  EXPECT_EQ(back.rigids[0].texture_resolution[1], 256);
  EXPECT_EQ(back.frames[0].surface_files.at("mirror"), "surface_mirror.0000.exr");
}

}  // namespace
}  // namespace dp::io
